// The suites' shared precompiled header (tests/CMakeLists.txt) needs a target of its own
// to be built in; this file is that target's only source.
