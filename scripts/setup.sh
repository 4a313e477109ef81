#!/usr/bin/env bash
# Installs every Debian package that building, testing and benchmarking Riemesh needs.
# Idempotent: safe to run again. Runs apt-get as root, or through sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config    # toolchain
  ccache                                          # compiler cache (build.sh uses it when present)
  clang libclang-rt-14-dev                        # fuzzers (libFuzzer runtime) and the sanitizer build
  libgtest-dev libgmock-dev libbenchmark-dev      # tests and benchmarks
  libcli11-dev libeigen3-dev                      # command line, small dense algebra
  libcairo2-dev                                   # PNG/SVG rendering
  python3-numpy python3-meshio time               # independent checks (shared/bench, validators)
  gmsh                                            # independent .msh/.mesh reader in the io tests
  freefem++                                       # FreeFem reads our 2D/3D .mesh (validators, client)
  tetgen                                          # 3D Delaunay comparison (bench/delaunay3d_vs_tetgen.sh)
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
