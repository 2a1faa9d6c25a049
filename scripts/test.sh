#!/usr/bin/env bash
# Builds and runs the whole test suite: the release build, then the same suite built with
# AddressSanitizer and UndefinedBehaviorSanitizer (minus paper_result, too slow there, and
# valgrind_render, since valgrind cannot run sanitized binaries), then every libFuzzer target
# for 60 s (scripts/fuzz.sh). Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage=$SECONDS
# took WHAT: how long the stage since the last call took (the suite's budget is in docs/testing.md)
took() { echo "== $1 took $((SECONDS - stage)) s"; stage=$SECONDS; }
scripts/build.sh
took "release build (with packages)"
echo "== tests (release build)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
took "release tests"
echo "== tests (ASan + UBSan build)"
# -O1 (what the AddressSanitizer documentation suggests) and line tables only (-g1, enough for
# file:line in a sanitizer's stack trace): about half the build time of -O2 -g, tests as fast
# (docs/testing.md).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXGAIT_SANITIZE=ON \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
      -DHEXGAIT_BUILD_BENCHMARKS=OFF -DHEXGAIT_WERROR=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
took "sanitizer build"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0 \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "paper_result|valgrind_render"
took "sanitizer tests"
echo "== fuzzing (libFuzzer + ASan + UBSan, 60 s per target)"
scripts/fuzz.sh 60
took "fuzzing (with its build)"
echo "== all tests passed in $((SECONDS - start)) s"
