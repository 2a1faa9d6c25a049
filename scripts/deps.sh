#!/usr/bin/env bash
# Installs the Debian 12 packages hexgait needs, when any is missing. Safe to run repeatedly.
#   scripts/deps.sh          what building and running need (scripts/main.sh)
#   scripts/deps.sh --test   also what only the tests need (scripts/test.sh)
set -euo pipefail
packages=(
  cmake g++ make ninja-build pkg-config python3
  libeigen3-dev libcli11-dev nlohmann-json3-dev   # model, flags, data files
  libboost-dev                                    # Boost.Odeint: the reference ODE solution
  libosmesa6-dev libpng-dev                       # off-screen rendering (OSMesa), PNG
  libegl-dev libegl-mesa0                         # off-screen rendering (EGL)
  libavcodec-dev libavformat-dev libswscale-dev   # H.264 movies (libx264 through libavcodec)
  libfreetype-dev fonts-dejavu-core               # captions in a real font
  gnuplot-nox                                     # figures (pngcairo and svg terminals)
  libopenmpi-dev openmpi-bin                      # evolve across MPI ranks (optional at build)
  python3-dev pybind11-dev python3-pybind11       # the Python module (optional at build)
  python3-numpy
)
if [ "${1:-}" = "--test" ]; then
  packages+=(
    libgtest-dev libbenchmark-dev                 # tests and micro-benchmarks
    ffmpeg valgrind                               # movie benchmark baseline, leak check
    chromium                                      # the report and replay page tests (headless)
    python3-pil                                   # the replay test's image comparison
    clang libclang-rt-14-dev                      # sanitizer build and libFuzzer targets
    python3-pytest                                # the Python module's tests
    python3-pandas python3-nbclient python3-ipykernel  # load_archive, the notebook in examples/
    python3-cmaes                                 # examples/: CMA-ES against the paper's GA
    python3-sklearn                               # tests/python: the Gaussian process checked
    hyperfine strace                              # scripts/startup.sh
  )
elif [ $# -gt 0 ]; then
  echo "usage: scripts/deps.sh [--test]" >&2
  exit 2
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "deps: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "deps: missing packages and not root; run as root or: sudo apt-get install ${missing[*]}" >&2
    exit 1
  fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
