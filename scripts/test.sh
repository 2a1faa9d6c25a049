#!/usr/bin/env bash
# The test suite, in two tiers (docs/testing.md):
#   scripts/test.sh --quick   after every change: the release build brought up to date, then the
#                             tests labelled `quick` (every layer: unit tests, layering, goldens on
#                             the EGL backend, one run of every command, a sample of every class
#                             of bad input); at most 2 minutes on 2 cores.
#   scripts/test.sh           everything (what .ci/run calls): packages, the release build and
#                             its whole suite, then one clang build with AddressSanitizer and
#                             UndefinedBehaviorSanitizer that runs the whole suite again (minus
#                             paper_result, too slow there; valgrind_render, since valgrind
#                             cannot run sanitized binaries; and replay_page, which is Chromium's
#                             time but for the page, written sanitized by cli_smoke) and serves the libFuzzer targets,
#                             each fuzzed for 17 s. Prints each stage's time; exits non-zero on
#                             any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cmake_generator.sh
start=$SECONDS
stage=$SECONDS
# took WHAT: how long the stage since the last call took (the budget is in docs/testing.md)
took() { echo "== $1 took $((SECONDS - stage)) s"; stage=$SECONDS; }
jobs=$(nproc)

if [ "${1:-}" = "--quick" ]; then
  scripts/build.sh
  took "release build (up to date)"
  echo "== quick tests (release build)"
  ctest --test-dir build --output-on-failure -j"$jobs" -L quick -E 'GoldenTest\..*/osmesa$'
  took "quick tests"
  echo "== quick tier passed in $((SECONDS - start)) s"
  exit 0
elif [ $# -gt 0 ]; then
  echo "usage: scripts/test.sh [--quick]" >&2
  exit 2
fi

scripts/build.sh
took "release build (with packages)"
# cli_bad_input_sample is the quick tier's subset of the two shards: the whole suite skips it.
echo "== tests (release build)"
ctest --test-dir build --output-on-failure -j"$jobs" -E "cli_bad_input_sample"
took "release tests"

echo "== sanitizer and fuzz build (clang, ASan + UBSan, libFuzzer coverage)"
# -O1 (what the AddressSanitizer documentation suggests) and line tables only (-g1, enough for
# file:line in a sanitizer's stack trace). One build for the sanitized suite and the fuzzers.
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DHEXGAIT_SANITIZE=ON -DHEXGAIT_FUZZ=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DHEXGAIT_BUILD_BENCHMARKS=OFF -DHEXGAIT_WERROR=ON -DHEXGAIT_UNIT_SHARDS=4 >/dev/null
cmake --build build-asan -j"$jobs"
took "sanitizer and fuzz build"
echo "== tests (ASan + UBSan build)"
# intercept_tls_get_addr=0: clang 14's __tls_get_addr interceptor can take a dynamic TLS block
# of a dlopen'ed library (Mesa, Open MPI) for a pre-2.25 glibc header and hand LeakSanitizer's
# tracer a bogus range, which crashes it at exit ("Tracer caught signal 11") now and then.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/support/lsan.supp:print_suppressions=0 \
  ctest --test-dir build-asan --output-on-failure -j"$jobs" \
  -E "paper_result|valgrind_render|replay_page|cli_bad_input_sample|cli_same_bits"
took "sanitizer tests"
echo "== fuzzing (libFuzzer + ASan + UBSan, 17 s per target)"
scripts/fuzz.sh 17 build-asan
took "fuzzing"
echo "== all tests passed in $((SECONDS - start)) s"
