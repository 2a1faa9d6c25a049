#!/usr/bin/env bash
# Configures and builds the release build in build/ (installing Debian packages if missing).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHEXGAIT_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
