#!/usr/bin/env bash
# Builds PaperFold with ThreadSanitizer and runs the test suites under it, so that the
# project's own code is shown race-free (docs/safety.md).
#   scripts/tsan.sh            every suite but the physics-only ones (tests/CMakeLists.txt)
#   scripts/tsan.sh --threads  only the suites that run more than one thread of the
#                              project's (the editor with its simulation thread and its
#                              export thread, the viewport, and the step on several
#                              threads): what CI runs, to stay within its time
# Other arguments go to ctest, e.g. `scripts/tsan.sh -R test_editor`
# (every share of the editor suite: test_editor.1, .2 and, under ThreadSanitizer, .3).
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
ctest_args=()
for arg in "$@"; do
    if [ "$arg" = "--threads" ]; then
        targets=(--target test_editor test_viewport test_determinism)
        # Two at a time, longest first (tests/CMakeLists.txt orders the editor suite's
        # three shares and the step's worker threads by COST), the viewport last.
        ctest_args+=(-R '^(test_editor\.[0-9]+|test_viewport|test_determinism_threads)$' -j2)
    else
        ctest_args+=("$arg")
    fi
done
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPAPERFOLD_SANITIZER=thread -DPAPERFOLD_WERROR=ON
cmake --build build-tsan "${targets[@]}"
# halt_on_error: a report fails its test (exit 66) instead of scrolling past.
export TSAN_OPTIONS="suppressions=$PWD/tests/tsan.supp halt_on_error=1 second_deadlock_stack=1 report_signal_unsafe=0"
ctest --test-dir build-tsan --output-on-failure "${ctest_args[@]}"
