#!/usr/bin/env bash
# One-command set-up on a fresh Debian 12 machine (as root):
#   bash scripts/setup.sh          install what is missing, build, run the default example into ./output/
#   bash scripts/setup.sh test     the same, then run the whole test suite (this is what CI runs)
set -euo pipefail
mode=${1:-example}
case "$mode" in example|test) ;; *) echo "usage: bash scripts/setup.sh [example|test]" >&2; exit 2;; esac
cd "$(dirname "$0")/.."

# Every Debian package the project needs: build tools, libraries, and the Python used for plots.
packages=(cmake g++ make pkg-config git clang-format
          libeigen3-dev libtbb-dev libyaml-cpp-dev libvtk9-dev libcgal-dev libgtest-dev libgmock-dev
          libmuparser-dev libcli11-dev libfmt-dev libbenchmark-dev
          python3 python3-numpy python3-matplotlib python3-vtk9)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

werror=OFF
[ -n "${CI:-}" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMPM_WARNINGS_AS_ERRORS=$werror
cmake --build build -j "$(nproc)"

if [ "$mode" = example ]; then
  ./build/apps/mpm run examples/02_two_disks/scene.yaml -o output
  echo "Open output/particles.pvd in ParaView."
else
  ctest --test-dir build --output-on-failure -j "$(nproc)"
fi
