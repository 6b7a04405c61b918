#!/usr/bin/env bash
# clang-tidy (checks in .clang-tidy) on the library sources, warnings as errors; the test suite runs it as
# the tests `clang_tidy_K` (label tidy), one part each.
#   bash scripts/tidy.sh [-p BUILD]                every .cpp of libmpm/src and a generated make_scheme
#                                                   unit (the scheme and shape headers)
#   bash scripts/tidy.sh [-p BUILD] --part K/N      the K-th of N parts of that list (every N-th file from the
#                                                   K-th), one clang-tidy at a time: ctest runs the parts side by side
#   bash scripts/tidy.sh [-p BUILD] --changed [REV] the library sources changed since REV (default main)
#   bash scripts/tidy.sh [-p BUILD] FILE...         the files given
# BUILD (default build/) must hold compile_commands.json (any configured build does).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
if [ "${1:-}" = -p ]; then build=$2; shift 2; fi
files=()
jobs=$(nproc)
if [ "${1:-}" = --changed ]; then
  mapfile -t files < <(git diff --name-only --diff-filter=d "${2:-main}" -- 'libmpm/src/*.cpp')
  [ ${#files[@]} -eq 0 ] && { echo "no library source changed since ${2:-main}"; exit 0; }
elif [ $# -gt 0 ] && [ "$1" != --part ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files 'libmpm/src/*.cpp')
  # the generated make_scheme units carry the scheme and shape headers: the 2D one, or three small ones
  units=("$build/libmpm/schemes/make_scheme_2d.cpp")
  [ -f "${units[0]}" ] || units=("$build"/libmpm/schemes/make_scheme_{1d_LinearHat,2d_CpdiQ4,3d_CubicBSpline}.cpp)
  files=("${units[@]}" "${files[@]}")  # the units first: with --part, each part has at most one
  if [ "${1:-}" = --part ]; then
    if ! [[ "${2:-}" =~ ^([0-9]+)/([0-9]+)$ ]] || [ "${BASH_REMATCH[1]}" -lt 1 ] ||
      [ "${BASH_REMATCH[1]}" -gt "${BASH_REMATCH[2]}" ]; then
      echo "--part K/N with 1 <= K <= N, not '${2:-}'" >&2
      exit 2
    fi
    part=${BASH_REMATCH[1]} parts=${BASH_REMATCH[2]} all=("${files[@]}") files=() jobs=1
    for ((i = part - 1; i < ${#all[@]}; i += parts)); do files+=("${all[i]}"); done
  fi
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "$build/compile_commands.json not found: configure first (cmake -S . -B $build)" >&2
  exit 2
fi
# The precompiled headers of the build (MPM_PRECOMPILED_HEADERS, cmake/precompiled_headers.cmake) are GCC's, which
# clang cannot read: clang-tidy gets the compile commands without them, so it reads each source as written.
commands=$(mktemp -d)
trap 'rm -rf "$commands"' EXIT
sed -E 's# -Winvalid-pch -include [^ ]*cmake_pch\.hxx##g' "$build/compile_commands.json" >"$commands/compile_commands.json"
echo "clang-tidy on ${#files[@]} files"
printf '%s\n' "${files[@]}" |
  xargs -P "$jobs" -I{} clang-tidy -p "$commands" --quiet --warnings-as-errors='*' --extra-arg=-Wno-unknown-warning-option {} 2> >(grep -v "warnings generated" >&2)
