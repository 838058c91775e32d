#!/bin/sh
# `uabt prove` on the peers' model-checking benchmark families, as whole processes: writes each
# mission with `uabt_bench prove-family`, runs
#   /usr/bin/time -v uabt prove DIR --engine E --format json
# per size and engine, and prints a Markdown table (family, size, tree nodes, engine, verdicts,
# states, wall s, max RSS MB). An engine this build lacks shows as "unsupported"; a run longer
# than UABT_PROVE_TIMEOUT seconds (default 600) is stopped and shows as "timeout".
#
#   sh tests/bench/prove_families.sh [--quick]
#   UABT_PROVE_ENGINES="explicit" UABT_PROVE_COUNTERS="2 3 4" sh tests/bench/prove_families.sh
#   UABT_PROVE_FAMILIES="preflight lunar" UABT_PROVE_TIMEOUT=120 sh tests/bench/prove_families.sh
set -eu
cd "$(dirname "$0")/../.."
quick=${1:-}
dir=${UABT_BENCH_BUILD_DIR:-build-bench}
engines=${UABT_PROVE_ENGINES:-explicit symbolic}
counters=${UABT_PROVE_COUNTERS:-2 3}
families=${UABT_PROVE_FAMILIES:-binary checklist preflight lunar lunar_reserve}
limit=${UABT_PROVE_TIMEOUT:-600}
if [ "$quick" = "--quick" ]; then
  tree_sizes="23 71 263"
  checklist_sizes="5 10 20"
  preflight_sizes="10 20"
else
  tree_sizes="23 71 263 1031 2055"
  checklist_sizes="5 10 20 50 65"
  preflight_sizes="10 20 50 100"
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

# measure LABEL SIZE MISSION_DIR FAMILY: one row per engine. FAMILY is what `uabt_bench
# prove-family` printed: the tree's nodes and the expected verdicts (`Id=verdict[@tick]`); a row
# whose verdicts differ from them says so.
measure() {
  nodes=${4%% *}
  expected=$(echo "${4#* }" | tr ' ' '\n' | sed 's/@.*//' | sort | tr '\n' ' ' | sed 's/ $//')
  for engine in $engines; do
    status=0
    /usr/bin/time -v -o "$out/time" timeout "$limit" "$uabt" prove "$3" --engine "$engine" \
      --format json >"$out/json" 2>"$out/err" || status=$?
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0;
             for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$out/time")
    rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$out/time")
    if [ "$status" = 124 ]; then
      verdicts="timeout: stopped after $limit s"
      states="-"
    elif [ -s "$out/json" ]; then
      verdicts=$(awk -F'"' '/"id":/ { id = $4 } /"verdict":/ && id != "" { printf "%s%s=%s",
                   sep, id, $4; sep = ", "; id = "" }' "$out/json")
      states=$(awk -F'[:,]' '/^  "states":/ { gsub(/ /, "", $2); print $2; exit }' "$out/json")
      got=$(echo "$verdicts" | sed 's/, /\n/g' | sort | tr '\n' ' ' | sed 's/ $//')
      [ "$got" = "$expected" ] || verdicts="$verdicts (WRONG: expected $expected)"
    else
      verdicts="unsupported: $(head -n 1 "$out/err" | sed "s/^uabt: prove: //" | cut -c1-48) (exit $status)"
      states="-"
    fi
    echo "| $1 | $2 | $nodes | $engine | $verdicts | $states | $wall | $rss |"
  done
}

echo "uabt prove, $build_type build in $dir, $(nproc) cores, $(date -u +%Y-%m-%d)"
echo
echo "| family | size | tree nodes | engine | verdicts | states | wall s | max RSS MB |"
echo "|---|---:|---:|---|---|---:|---:|---:|"
has() { case " $families " in *" $1 "*) return 0 ;; esac; return 1; }
if has binary; then
  for v in $counters; do
    for n in $tree_sizes; do
      m="$out/binary-$v-$n"
      family=$("$bench" prove-family binary "$n" "$m" --counters "$v")
      measure "binary tree, $v counters" "$n" "$m" "$family"
    done
  done
fi
if has checklist; then
  for n in $checklist_sizes; do
    m="$out/checklist-$n"
    measure "checklist" "N = $n" "$m" "$("$bench" prove-family checklist "$n" "$m")"
  done
fi
if has preflight; then
  for n in $preflight_sizes; do
    m="$out/preflight-$n"
    measure "pre-flight checklist" "N = $n" "$m" "$("$bench" prove-family preflight "$n" "$m")"
  done
fi
if has lunar; then
  m="$out/lunar"
  measure "lunar sortie" "1" "$m" "$("$bench" prove-family lunar 1 "$m")"
fi
if has lunar_reserve; then
  m="$out/lunar_reserve"
  measure "lunar sortie, reserve" "1" "$m" "$("$bench" prove-family lunar_reserve 1 "$m")"
fi
