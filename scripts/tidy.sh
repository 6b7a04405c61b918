#!/usr/bin/env bash
# clang-tidy (checks in .clang-tidy) on the library sources, warnings as errors; the test suite runs it as
# the test `clang_tidy` (label tidy).
#   bash scripts/tidy.sh [-p BUILD]                every .cpp of libmpm/src and a generated make_scheme
#                                                   unit (the scheme and shape headers)
#   bash scripts/tidy.sh [-p BUILD] --changed [REV] the library sources changed since REV (default main)
#   bash scripts/tidy.sh [-p BUILD] FILE...         the files given
# BUILD (default build/) must hold compile_commands.json (any configured build does).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
if [ "${1:-}" = -p ]; then build=$2; shift 2; fi
files=()
if [ "${1:-}" = --changed ]; then
  mapfile -t files < <(git diff --name-only --diff-filter=d "${2:-main}" -- 'libmpm/src/*.cpp')
  [ ${#files[@]} -eq 0 ] && { echo "no library source changed since ${2:-main}"; exit 0; }
elif [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files 'libmpm/src/*.cpp')
  # the generated make_scheme units carry the scheme and shape headers: the 2D one, or three small ones
  units=("$build/libmpm/schemes/make_scheme_2d.cpp")
  [ -f "${units[0]}" ] || units=("$build"/libmpm/schemes/make_scheme_{1d_LinearHat,2d_CpdiQ4,3d_CubicBSpline}.cpp)
  files+=("${units[@]}")
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "$build/compile_commands.json not found: configure first (cmake -S . -B $build)" >&2
  exit 2
fi
echo "clang-tidy on ${#files[@]} files"
printf '%s\n' "${files[@]}" |
  xargs -P "$(nproc)" -I{} clang-tidy -p "$build" --quiet --warnings-as-errors='*' --extra-arg=-Wno-unknown-warning-option {} 2> >(grep -v "warnings generated" >&2)
