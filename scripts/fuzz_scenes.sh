#!/usr/bin/env bash
# The scene-parser fuzz test at any length: bash scripts/fuzz_scenes.sh N SEED [BUILD_DIR [KEEP_DIR]]
# runs N mutated scenes (tests/apps/test_scene_fuzz.cpp: every example and bad-scene fixture mutated, each case
# through `mpm check`, every fourth through a 2-step `mpm run`) from SEED, prints the counts of each outcome and
# copies every failing case into KEEP_DIR (default fuzz_failures). The suite runs 400 cases of seed 1.
# Long runs share the machine: start them with `nice -n 19`.
set -euo pipefail
cases=${1:?usage: fuzz_scenes.sh N SEED [BUILD_DIR [KEEP_DIR]]}
seed=${2:?usage: fuzz_scenes.sh N SEED [BUILD_DIR [KEEP_DIR]]}
build=${3:-build}
keep=${4:-fuzz_failures}
MPM_FUZZ_CASES=$cases MPM_FUZZ_SEED=$seed MPM_FUZZ_KEEP=$(realpath -m "$keep") \
  "$build/tests/test_apps" --gtest_filter='SceneFuzz.*'
