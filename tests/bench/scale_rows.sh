#!/bin/sh
# The scale checklist's rows (BehaVerify's checklist, wide trees, long requirement sets,
# bounded diagnostics) as whole processes: writes each row's mission with uabt_bench, then runs
#   /usr/bin/time -f "%e %M" UABT COMMAND DIR
# for every binary given, one row after the other, so "before" and "after" share one run.
# Prints a Markdown table: row, command, then per binary wall s, max RSS MB and the last line
# of its output (the verdict). A run longer than UABT_ROW_TIMEOUT seconds (default 120) is
# stopped and shows as "timeout".
#
#   sh tests/bench/scale_rows.sh build/uabt
#   sh tests/bench/scale_rows.sh /path/to/old/uabt build/uabt
set -eu
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] || { echo "usage: sh tests/bench/scale_rows.sh UABT [UABT…]" >&2; exit 2; }
bench=${UABT_BENCH:-build/tests/bench/uabt_bench}
[ -x "$bench" ] || { echo "no $bench: configure with -DUABT_BENCH=ON and build uabt_bench" >&2; exit 2; }
limit=${UABT_ROW_TIMEOUT:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bench" prove-family recheck 50 "$work/recheck50" >/dev/null
"$bench" prove-family recheck 100 "$work/recheck100" >/dev/null
"$bench" prove-family recheck_kept 50 "$work/kept50" >/dev/null
"$bench" prove-family recheck_kept 100 "$work/kept100" >/dev/null
"$bench" verify-family ported 200000 "$work/ported" >/dev/null
"$bench" verify-family reals 2048 "$work/reals2048" >/dev/null
"$bench" verify-family reals 10008 "$work/reals10008" >/dev/null
"$bench" prove-family wide_disjuncts 60000 "$work/disjuncts" >/dev/null
"$bench" prove-family wide_enum 4096 "$work/enum" >/dev/null
"$bench" verify-family undeclared 20000 "$work/undeclared" >/dev/null
"$bench" verify-family noise 5242880 "$work/noise" >/dev/null
# An action whose duration is any number of ticks up to the largest a world.json may give, in
# a mission whose guarantee is proved (so the search explores every state).
"$bench" prove-family recheck_kept 2 "$work/ticks" >/dev/null
sed 's/"ticks": \[1, 2\]/"ticks": [1, 9223372036854775807]/' "$work/ticks/world.json" \
  >"$work/ticks/w" && mv "$work/ticks/w" "$work/ticks/world.json"
# msl_curiosity as the issue measured it: Req1 guarded by OnDust and 60,000 depths.
cp -r missions/msl_curiosity "$work/msl60k"
printf 'integer depth in [0, 100000]\n' >>"$work/msl60k/domain.fret"
awk '/^Req1: In navigation if OnDust / { g = "depth = 0"
                                         for (k = 1; k < 60000; k++) g = g " | depth = " k
                                         sub(/if OnDust /, "if OnDust \\& (" g ") ") } { print }' \
  missions/msl_curiosity/requirements.fret >"$work/msl60k/requirements.fret"

rows="checklist_N=50|prove|recheck50
checklist_N=100|prove|recheck100
checklist_N=50,_kept|prove|kept50
checklist_N=100,_kept|prove|kept100
Sequence_of_200,000_ported_actions|verify|ported
2,048_real-valued_guards|verify|reals2048
10,008_real-valued_guards|verify|reals10008
one_guard_of_60,000_disjuncts_(family)|gate|disjuncts
msl_curiosity,_Req1_guarded_by_60,000_disjuncts|gate|msl60k
enum_of_4,096_values_(family)|prove|enum
enum_of_4,096_values_(family)|gate|enum
ticks_[1,_2^63-1]|prove|ticks
20,000_undeclared_names|verify|undeclared
5_MB_of_noise_as_requirements.fret|verify|noise"

printf '| row | command |'
for u in "$@"; do printf ' %s |' "$u"; done
printf '\n|---|---|'
for _ in "$@"; do printf -- '---|'; done
printf '\n'
echo "$rows" | while IFS='|' read -r name command dir; do
  printf '| %s | `uabt %s` |' "$(echo "$name" | tr _ ' ')" "$command"
  for u in "$@"; do
    out="$work/out"
    extra=""
    [ "$command" = gate ] && extra="--out $work/gate-report"
    status=0
    # shellcheck disable=SC2086
    timeout "$limit" /usr/bin/time -f "%e %M" -o "$work/time" "$u" "$command" "$work/$dir" \
      $extra >"$out" 2>&1 </dev/null || status=$?
    if [ "$status" -eq 124 ] || [ ! -s "$work/time" ]; then
      printf ' timeout (%s s) |' "$limit"
    else
      t=$(tail -1 "$work/time")
      last=$(grep -av '^$' "$out" | tail -1 | cut -c1-60 | tr '|' '/')
      printf ' %s s, %s MB: %s |' "${t% *}" "$(( ${t#* } / 1024 ))" "$last"
    fi
    rm -f "$work/time"
  done
  printf '\n'
done
