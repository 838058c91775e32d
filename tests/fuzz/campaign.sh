#!/bin/sh
# Runs every fuzz target (or those named in TARGETS) for SECONDS (default 600) one after the
# other and prints, per target, the executions, the final coverage and the number of crashes.
# Usage:
#
#   sh tests/fuzz/campaign.sh [SECONDS] [WORK_DIR] [TARGETS...]
#   sh tests/fuzz/campaign.sh 600 /tmp/work world uplink     # two targets only
#
# WORK_DIR (default: a new temporary directory) receives the growing corpora, the logs and any
# crash-* / timeout-* / oom-* files. Exits 1 when any target found something.
set -eu
cd "$(dirname "$0")/../.."
seconds=${1:-600}
work=${2:-$(mktemp -d)}
[ $# -ge 2 ] && shift 2 || shift $#
targets=${*:-fretish domain fret_json bt_xml pipeline world uplink scenario scenario_uplink nodes trace}
bin=${UABT_FUZZ_BUILD_DIR:-build-fuzz}/tests/fuzz
mkdir -p "$work"
found=0
printf '%-16s %12s %10s %8s %8s\n' target executions exec/s cov crashes
for target in $targets; do
  mkdir -p "$work/$target/corpus" "$work/$target/artifacts"
  seeds="tests/fuzz/corpus/$target"
  [ -d "tests/fuzz/regressions/$target" ] && seeds="$seeds tests/fuzz/regressions/$target"
  # shellcheck disable=SC2086 # seeds is a list of directories
  "$bin/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -print_final_stats=1 -dict="tests/fuzz/dict/$target.dict" \
    -artifact_prefix="$work/$target/artifacts/" "$work/$target/corpus" $seeds \
    >"$work/$target/log" 2>&1 || true
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$target/log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/$target/log")
  cov=$(grep -o 'cov: [0-9]*' "$work/$target/log" | tail -1 | cut -d' ' -f2)
  crashes=$(find "$work/$target/artifacts" -type f | wc -l)
  [ "$crashes" -eq 0 ] || found=1
  printf '%-16s %12s %10s %8s %8s\n' "$target" "${runs:-?}" "${rate:-?}" "${cov:-?}" "$crashes"
done
echo "work directory: $work"
exit "$found"
