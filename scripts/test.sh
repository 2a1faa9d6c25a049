#!/usr/bin/env bash
# Builds and runs the whole test suite: the release build, then the same suite built with
# AddressSanitizer and UndefinedBehaviorSanitizer (minus paper_result, too slow there, and
# valgrind_render, since valgrind cannot run sanitized binaries), then every libFuzzer target
# for 60 s (scripts/fuzz.sh). Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/build.sh
echo "== tests (release build)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "== tests (ASan + UBSan build)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXGAIT_SANITIZE=ON \
      -DHEXGAIT_BUILD_BENCHMARKS=OFF -DHEXGAIT_WERROR=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0 \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "paper_result|valgrind_render"
echo "== fuzzing (libFuzzer + ASan + UBSan, 60 s per target)"
scripts/fuzz.sh 60
echo "== all tests passed in $((SECONDS - start)) s"
