#!/usr/bin/env bash
# clang-tidy (checks in .clang-tidy) on the library sources, warnings as errors; the test suite runs it as
# the tests `clang_tidy_K` (label tidy), one part each.
#   bash scripts/tidy.sh [-p BUILD]                every .cpp of libmpm/src and a generated make_scheme
#                                                   unit (the scheme and shape headers)
#   bash scripts/tidy.sh [-p BUILD] --part K/N      the K-th of N parts of that list, one clang-tidy at a time:
#                                                   ctest runs the parts side by side. The library sources are
#                                                   checked as one translation unit per folder (BUILD/tidy_units/,
#                                                   each #includes the folder's sources), and the parts share the
#                                                   units out by their number of sources: clang-tidy then
#                                                   parses the headers they share (Eigen, TBB, fmt, the engine's) once
#                                                   per folder instead of once per source, which is most of its time
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
  files=("${units[@]}" "${files[@]}")
  if [ "${1:-}" = --part ]; then
    if ! [[ "${2:-}" =~ ^([0-9]+)/([0-9]+)$ ]] || [ "${BASH_REMATCH[1]}" -lt 1 ] ||
      [ "${BASH_REMATCH[1]}" -gt "${BASH_REMATCH[2]}" ]; then
      echo "--part K/N with 1 <= K <= N, not '${2:-}'" >&2
      exit 2
    fi
    part=${BASH_REMATCH[1]} parts=${BASH_REMATCH[2]} jobs=1 unity=1
  fi
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "$build/compile_commands.json not found: configure first (cmake -S . -B $build)" >&2
  exit 2
fi
# The precompiled headers of the build (MPM_PRECOMPILED_HEADERS, cmake/precompiled_headers.cmake) are GCC's, which
# clang cannot read: clang-tidy gets the compile commands without them, so it reads each source as written. GCC's
# optimiser parameters (--param=..., the top CMakeLists.txt) mean nothing to clang, which calls them unused.
commands=$(mktemp -d)
trap 'rm -rf "$commands"' EXIT
sed -E 's# -Winvalid-pch -include [^ ]*cmake_pch\.hxx##g; s# --param=[^ ]*##g' "$build/compile_commands.json" \
  >"$commands/compile_commands.json"
# A library compiled in unity batches (MPM_UNITY_BUILD, cmake/unity_libraries.cmake) lists its batches, not its
# sources: each source a batch includes gets the batch's command, so that clang-tidy checks it as written.
/usr/bin/env python3 - "$commands/compile_commands.json" <<'PY'
import json, os, re, sys
db = json.load(open(sys.argv[1]))
known = {os.path.realpath(e["file"]) for e in db}
for e in list(db):
    if "/Unity/unity_" not in e["file"]: continue
    for source in re.findall(r'^#include "([^"]+)"', open(e["file"]).read(), re.M):
        if os.path.realpath(source) in known: continue
        entry = dict(e, file=source)
        if "arguments" in e: entry["arguments"] = [source if a == e["file"] else a for a in e["arguments"]]
        else: entry["command"] = e["command"].replace(e["file"], source)
        db.append(entry)
json.dump(db, open(sys.argv[1], "w"))
PY
if [ "${unity:-0}" = 1 ]; then
  # One unit per folder of libmpm/src: BUILD/tidy_units/<folder>.cpp includes the folder's sources and compiles
  # with the command of the first of them (the sources of a folder share their target).
  mapfile -t files < <(/usr/bin/env python3 - "$commands/compile_commands.json" "$build/tidy_units" "$part" "$parts" \
    "${files[@]}" <<'PY'
import json, os, sys
db_path, out_dir, part, parts, files = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5:]
db = json.load(open(db_path))
by_file = {os.path.realpath(e["file"]): e for e in db}
groups, order = {}, []
for f in files:
    real = os.path.realpath(f)
    key = os.path.dirname(real) if "/libmpm/src/" in real else real
    if key not in groups: groups[key], _ = [], order.append(key)
    groups[key].append(real)
# the units to the parts, heaviest first to the lightest part (a generated make_scheme unit weighs as six sources)
weight = {k: 6 if "/libmpm/src/" not in k else len(groups[k]) for k in order}
load, mine = [0] * parts, []
for key in sorted(order, key=lambda k: -weight[k]):
    lightest = load.index(min(load))
    load[lightest] += weight[key]
    if lightest == part - 1: mine.append(key)
os.makedirs(out_dir, exist_ok=True)
for key in mine:
    members = groups[key]
    if len(members) == 1:
        print(members[0]); continue
    unit = os.path.join(os.path.realpath(out_dir), f"{os.path.basename(key)}.cpp")
    text = "".join(f'#include "{m}"  // NOLINT(bugprone-suspicious-include)\n' for m in members)
    if not os.path.exists(unit) or open(unit).read() != text: open(unit, "w").write(text)
    entry = dict(by_file[members[0]])
    if "arguments" in entry:
        entry["arguments"] = [unit if os.path.realpath(os.path.join(entry["directory"], a)) == members[0] else a
                              for a in entry["arguments"]]
    else:
        entry["command"] = entry["command"].replace(entry["file"], unit)
    entry["file"] = unit
    db.append(entry)
    print(unit)
json.dump(db, open(db_path, "w"))
PY
  )
fi
echo "clang-tidy on ${#files[@]} files"
tidy() { clang-tidy -p "$commands" --quiet --warnings-as-errors='*' --extra-arg=-Wno-unknown-warning-option "$@"; }
if [ "${unity:-0}" = 1 ]; then
  # A unit whose sources do not compile together (helpers of the same name in their anonymous namespaces) is
  # checked source by source; any other finding stands.
  status=0
  for f in "${files[@]}"; do
    out=$(tidy "$f" 2>&1) && { printf '%s' "$out" | grep -v "warnings generated" || true; continue; }
    if [[ "$f" == */tidy_units/* ]] && grep -q "redefinition of\|\[clang-diagnostic-error\]" <<<"$out"; then
      mapfile -t members < <(sed -E 's/^#include "([^"]+)".*/\1/' "$f")
      echo "$(basename "$f"): its sources do not compile as one unit; checking them one by one"
      for m in "${members[@]}"; do tidy "$m" 2> >(grep -v "warnings generated" >&2) || status=1; done
    else
      printf '%s\n' "$out" | grep -v "warnings generated" >&2
      status=1
    fi
  done
  exit $status
fi
printf '%s\n' "${files[@]}" |
  xargs -P "$jobs" -I{} clang-tidy -p "$commands" --quiet --warnings-as-errors='*' --extra-arg=-Wno-unknown-warning-option {} 2> >(grep -v "warnings generated" >&2)
