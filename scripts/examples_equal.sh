#!/usr/bin/env bash
# Runs every example scene (examples/**/*.yaml) for a few steps with two builds of `mpm` and compares their
# output with `mpm diff --tolerance 0`: the check that a refactoring changed no bit of any example.
#   bash scripts/examples_equal.sh MPM_BEFORE MPM_AFTER [STEPS] [WORK_DIR]
# STEPS defaults to 40, WORK_DIR to a new temporary folder (kept, its path printed). Prints one line per scene
# (equal, DIFFERENT, or the exit status of a run that failed) and exits 1 when any scene differs or fails.
set -uo pipefail
if [ $# -lt 2 ]; then
  echo "usage: bash scripts/examples_equal.sh MPM_BEFORE MPM_AFTER [STEPS] [WORK_DIR]" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
steps=${3:-40}
work=${4:-$(mktemp -d /tmp/examples_equal.XXXXXX)}
mkdir -p "$work"
cd "$(dirname "$0")/.."
status=0
for scene in $(find examples -name '*.yaml' | sort); do
  if grep -q "model: user" "$scene"; then  # its library is built by its README (tests/user_material runs it)
    echo "$scene: skipped (a user material)"
    continue
  fi
  name=$(echo "${scene#examples/}" | tr '/' '_')
  name=${name%.yaml}
  "$before" run "$scene" --steps "$steps" -o "$work/$name.before" >"$work/$name.before.log" 2>&1
  rb=$?
  "$after" run "$scene" --steps "$steps" -o "$work/$name.after" >"$work/$name.after.log" 2>&1
  ra=$?
  if [ $rb -ne $ra ]; then
    echo "$scene: exit $rb before, $ra after"
    status=1
  elif "$after" diff "$work/$name.before" "$work/$name.after" --tolerance 0 >"$work/$name.diff" 2>&1; then
    echo "$scene: equal (exit $ra)"
  else
    echo "$scene: DIFFERENT (see $work/$name.diff)"
    status=1
  fi
done
echo "output in $work"
exit $status
