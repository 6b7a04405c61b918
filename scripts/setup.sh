#!/usr/bin/env bash
# One-command set-up on a fresh Debian 12 machine (as root):
#   bash scripts/setup.sh           install what is missing, build the `mpm` program and the Python package
#                                   (build/python: PYTHONPATH=build/python /usr/bin/python3 -c "import mpm"), run
#                                   the default example into ./output/
#   bash scripts/setup.sh install   the same, then `cmake --install build` (default prefix /usr/local): the
#                                   program, the libraries with their CMake package, and the Python package
#                                   where /usr/bin/python3 finds it
#   bash scripts/setup.sh test      install, build everything (library, program, tests, benchmarks) and run
#                                   the whole test suite (this is what CI runs)
#   bash scripts/setup.sh sanitize  install, build the program and the unit and stability tests with the
#                                   address and undefined-behaviour sanitizers in build-sanitize/, run
#                                   `ctest -L 'unit|stability'` there (any sanitizer report fails its test)
set -euo pipefail
mode=${1:-example}
case "$mode" in example|install|test|sanitize) ;; *) echo "usage: bash scripts/setup.sh [example|install|test|sanitize]" >&2; exit 2;; esac
cd "$(dirname "$0")/.."

# Every Debian package the project needs: build tools, libraries, the Python used for plots, and the Python
# package's bindings (pybind11, Python's headers), tests (pytest) and notebook execution (nbconvert, a kernel),
# MPI (OpenMPI's headers and mpirun: distributed runs; libvtk9-dev already pulls in the library), and
# valgrind (bench/count_instructions.sh: instruction counts where the wall time is too noisy), OpenCASCADE
# (geometry/: STEP, IGES and BREP bodies, MPM_WITH_OCCT; 37 MB, about 10 s to install), gfortran (the user
# materials' Fortran VUMAT and UMAT examples and their tests, physics/user_material).
packages=(cmake g++ make pkg-config git clang-format clang-tidy
          libeigen3-dev libtbb-dev libyaml-cpp-dev libvtk9-dev libcgal-dev libgtest-dev libgmock-dev
          libmuparser-dev libcli11-dev libfmt-dev libbenchmark-dev libhdf5-dev
          python3 python3-numpy python3-matplotlib python3-vtk9
          pybind11-dev python3-dev python3-pytest jupyter-nbconvert python3-ipykernel
          libopenmpi-dev openmpi-bin valgrind gfortran
          libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-ocaf-dev)
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
jobs=$(nproc)

if [ "$mode" = sanitize ]; then
  # The test programs of the unit and stability labels and the program test_apps runs; no benchmarks.
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DMPM_SANITIZE=ON -DMPM_BUILD_BENCH=OFF \
    -DMPM_WARNINGS_AS_ERRORS=$werror
  cmake --build build-sanitize -j "$jobs" --target mpm test_libmpm test_geometry test_apps test_physics test_stability
  # Undefined behaviour stops the test that meets it (by default UBSan only prints and goes on).
  export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  ctest --test-dir build-sanitize -L 'unit|stability' --output-on-failure -j "$jobs"
  exit 0
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMPM_WARNINGS_AS_ERRORS=$werror
if [ "$mode" = example ] || [ "$mode" = install ]; then
  # the program and the Python package only: the tests and benchmarks are built by `test`
  cmake --build build -j "$jobs" --target mpm
  if grep -q '^MPM_WITH_PYTHON:BOOL=ON' build/CMakeCache.txt; then cmake --build build -j "$jobs" --target mpm_python; fi
  if [ "$mode" = install ]; then
    cmake --install build
    exit 0
  fi
  ./build/apps/mpm run examples/02_two_disks/scene.yaml -o output
  echo "Open output/particles.pvd in ParaView. Python: PYTHONPATH=build/python /usr/bin/python3 -c 'import mpm'"
else
  cmake --build build -j "$jobs"
  ctest --test-dir build --output-on-failure -j "$jobs"
fi
