#!/bin/sh
# `uabt prove` on the peers' model-checking benchmark families, as whole processes: writes each
# mission with `uabt_bench prove-family`, runs
#   /usr/bin/time -v uabt prove DIR --engine E --format json
# per size and engine, and prints a Markdown table (family, size, tree nodes, engine, verdicts,
# states, wall s, max RSS MB). An engine this build lacks shows as "unsupported".
#
#   sh tests/bench/prove_families.sh [--quick]
#   UABT_PROVE_ENGINES="explicit" UABT_PROVE_COUNTERS="2 3 4" sh tests/bench/prove_families.sh
set -eu
cd "$(dirname "$0")/../.."
quick=${1:-}
dir=${UABT_BENCH_BUILD_DIR:-build-bench}
engines=${UABT_PROVE_ENGINES:-explicit symbolic}
counters=${UABT_PROVE_COUNTERS:-2 3}
if [ "$quick" = "--quick" ]; then
  tree_sizes="23 71 263"
  checklist_sizes="5 10 20"
else
  tree_sizes="23 71 263 1031 2055"
  checklist_sizes="5 10 20 50 65"
fi
# A new build directory is a Release one; an existing one keeps its build type (the table says
# which).
if [ -f "$dir/CMakeCache.txt" ]; then
  cmake -S . -B "$dir" -DUABT_BENCH=ON >/dev/null
else
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DUABT_BENCH=ON >/dev/null
fi
cmake --build "$dir" --target uabt_cli uabt_bench >/dev/null
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$dir/CMakeCache.txt")
bench="$dir/tests/bench/uabt_bench"
uabt="$dir/uabt"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# measure LABEL SIZE MISSION_DIR NODES: one row per engine.
measure() {
  for engine in $engines; do
    status=0
    /usr/bin/time -v -o "$out/time" "$uabt" prove "$3" --engine "$engine" --format json \
      >"$out/json" 2>"$out/err" || status=$?
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0;
             for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$out/time")
    rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$out/time")
    if [ -s "$out/json" ]; then
      verdicts=$(awk -F'"' '/"id":/ { id = $4 } /"verdict":/ && id != "" { printf "%s%s=%s",
                   sep, id, $4; sep = ", "; id = "" }' "$out/json")
      states=$(awk -F'[:,]' '/^  "states":/ { gsub(/ /, "", $2); print $2; exit }' "$out/json")
    else
      verdicts="unsupported: $(head -n 1 "$out/err" | sed "s/^uabt: prove: //" | cut -c1-48) (exit $status)"
      states="-"
    fi
    echo "| $1 | $2 | $4 | $engine | $verdicts | $states | $wall | $rss |"
  done
}

echo "uabt prove, $build_type build in $dir, $(nproc) cores, $(date -u +%Y-%m-%d)"
echo
echo "| family | size | tree nodes | engine | verdicts | states | wall s | max RSS MB |"
echo "|---|---:|---:|---|---|---:|---:|---:|"
for v in $counters; do
  for n in $tree_sizes; do
    m="$out/binary-$v-$n"
    nodes=$("$bench" prove-family binary "$n" "$m" --counters "$v" | cut -d' ' -f1)
    measure "binary tree, $v counters" "$n" "$m" "$nodes"
  done
done
for n in $checklist_sizes; do
  m="$out/checklist-$n"
  nodes=$("$bench" prove-family checklist "$n" "$m" | cut -d' ' -f1)
  measure "checklist" "N = $n" "$m" "$nodes"
done
