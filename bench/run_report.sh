#!/usr/bin/env bash
# The error-against-run-time report: builds bench/verification_report (Release) if needed, runs every case
# of the verification catalogue on its resolution ladder with every method registered for it, the CFL-factor
# search (bar, two disks) and the stiff/extreme cases, then draws the plots (matplotlib) and writes
# docs/VERIFICATION.md with docs/figures/verification/*.png.
#   bash bench/run_report.sh --quick     # the catalogue's standard ladders: about 4 minutes on the dev machine
#   bash bench/run_report.sh             # one finer resolution on every ladder: about 30 minutes
# Other arguments go to the program (`--threads N`, `--max-run-seconds S`, `--only TEXT`, `--no-cfl`, ...).
# With --only or --no-* the report is partial: it is written to the CSV directory, not to docs/.
# MPM_BUILD_DIR (default build/), MPM_JOBS (compile jobs, default 1) and MPM_REPORT_DIR (CSV, default
# $MPM_BUILD_DIR/verification_report) as for run_throughput.sh.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MPM_BUILD_DIR:-$root/build}"
jobs="${MPM_JOBS:-1}"
out="${MPM_REPORT_DIR:-$build/verification_report}"
python=/usr/bin/python3

if ! "$python" -c 'import matplotlib, numpy' 2>/dev/null; then
  echo "run_report.sh: $python needs numpy and matplotlib (apt-get install python3-numpy python3-matplotlib)" >&2
  exit 2
fi
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
elif ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt"; then
  echo "warning: $build is not a Release build; wall times will not be representative" >&2
fi
cmake --build "$build" --target verification_report -j "$jobs"

docs="$root/docs"
for a in "$@"; do
  case "$a" in
    --only | --no-cases | --no-cfl | --no-stability) docs="$out" ;;
  esac
done
"$build/bench/verification_report" --out "$out" "$@"
"$python" "$root/bench/make_verification_report.py" "$out" --docs "$docs" \
  --command "bash bench/run_report.sh${*:+ $*}"
