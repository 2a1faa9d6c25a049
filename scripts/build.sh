#!/usr/bin/env bash
# Configures and builds the release build in build/, installing Debian packages if missing.
#   scripts/build.sh          everything: hexgait, the Python module, tests and benchmarks
#   scripts/build.sh --main   only what the main job runs (hexgait and its MPI module)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cmake_generator.sh
if [ "${1:-}" = "--main" ]; then
  scripts/deps.sh
  # A build folder made by scripts/test.sh keeps its settings; a new one builds no tests.
  if [ ! -f build/CMakeCache.txt ]; then
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHEXGAIT_WERROR=ON \
          -DHEXGAIT_BUILD_TESTS=OFF -DHEXGAIT_BUILD_BENCHMARKS=OFF >/dev/null
  fi
  cmake --build build -j"$(nproc)" --target hexgait
elif [ $# -eq 0 ]; then
  scripts/deps.sh --test
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHEXGAIT_WERROR=ON \
        -DHEXGAIT_BUILD_TESTS=ON -DHEXGAIT_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build build -j"$(nproc)"
else
  echo "usage: scripts/build.sh [--main]" >&2
  exit 2
fi
