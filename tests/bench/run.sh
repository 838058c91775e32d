#!/bin/sh
# The whole benchmark harness in one command: a Release build with the benchmarks, then
# Google Benchmark over every stage (verify against the naive baseline, gate, load, compile,
# tick engine, prove), the scaling curves, the MSL gate as a whole process (20 runs), and
# `uabt prove` on the model-checking families (prove_families.sh).
#
#   sh tests/bench/run.sh [--quick]     (--quick: small sizes only, about a minute)
set -eu
cd "$(dirname "$0")/../.."
quick=${1:-}
dir=${UABT_BENCH_BUILD_DIR:-build-bench}
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DUABT_BENCH=ON >/dev/null
cmake --build "$dir" --target uabt uabt_bench
bench="$dir/tests/bench/uabt_bench"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "== Google Benchmark"
if [ "$quick" = "--quick" ]; then
  "$bench" --benchmark_filter='BM_Verify/|BM_NaiveVerify/1/|BM_Gate|BM_Compile/10/|BM_Tick'
  echo "== scaling (quick)"
  "$bench" scale --quick
else
  "$bench"
  echo "== scaling"
  "$bench" scale
fi
echo "== selection cost: Fig. 4 against --selection optimized"
"$bench" selection
echo "== uabt gate missions/msl_curiosity, whole process"
"$bench" process 20 "$dir/uabt" gate missions/msl_curiosity --out "$out"
echo "== uabt prove on the model-checking families (whole processes)"
UABT_BENCH_BUILD_DIR="$dir" sh tests/bench/prove_families.sh $quick
