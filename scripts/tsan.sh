#!/usr/bin/env bash
# Builds PaperFold with ThreadSanitizer and runs every test suite under it, so that
# the project's own code is shown race-free (docs/safety.md). Extra arguments go to
# ctest, e.g. `scripts/tsan.sh -R test_editor`.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPAPERFOLD_SANITIZER=thread -DPAPERFOLD_WERROR=ON
cmake --build build-tsan
# halt_on_error: a report fails its test (exit 66) instead of scrolling past.
export TSAN_OPTIONS="suppressions=$PWD/tests/tsan.supp halt_on_error=1 second_deadlock_stack=1 report_signal_unsafe=0"
ctest --test-dir build-tsan --output-on-failure "$@"
