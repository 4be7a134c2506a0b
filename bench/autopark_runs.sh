#!/usr/bin/env bash
# Whole Autopark exercise, headless in lockstep (simulator + component + referee), over several
# seeds and slot sizes: success (parked, no collision), mark, sim time to park, distance to the
# ideal pose, the planner's wall time per plan() call and the wall time per run, with medians.
# Prints one Markdown table row per world.
#   bench/autopark_runs.sh [BUILD_DIR] [SEEDS] [ALGORITHM] [WORLDS]
#   e.g. bench/autopark_runs.sh build "$(seq -s' ' 1 20)" planner "autopark_ackermann_1.3L"
set -euo pipefail
build="${1:-build}"
seeds="${2:-$(seq -s' ' 1 20)}"
algorithm="${3:-planner}"
worlds="${4:-autopark_ackermann_1.6L autopark_ackermann_1.4L autopark_ackermann_1.3L autopark_ackermann_1.2L autopark_ackermann autopark}"
out="$(mktemp -d)"
port=$((20000 + $$ % 20000))
median() { sort -g | awk 'NF {a[++n]=$1} END {if (n == 0) print "-"; else if (n % 2) print a[(n+1)/2]; else print (a[n/2] + a[n/2+1]) / 2}'; }
number() { grep "\"$1\"" "$2" | head -1 | sed 's/.*: \(-\?[0-9.]*\).*/\1/'; }
echo "| world | algorithm | parked, no collision | median mark | median park time s | median pose error m | median plan ms | max plan ms | median wall s |"
echo "|---|---|---|---|---|---|---|---|---|"
for world in $worlds; do
  ok=0; total=0
  : > "$out/mark"; : > "$out/time"; : > "$out/error"; : > "$out/plan"; : > "$out/wall"
  for seed in $seeds; do
    report="$out/$world-$seed.json" log="$out/$world-$seed.log"
    start=$(date +%s.%N)
    "$build/bin/aula" run autopark --headless --algorithm="$algorithm" --seed="$seed" --world="worlds/$world.world" \
      --report="$report" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$log" 2>&1 || true
    end=$(date +%s.%N)
    echo "$end - $start" | bc -l >> "$out/wall"
    total=$((total + 1))
    if grep -q '"parked": true' "$report" && [ "$(number collisions "$report")" = "0" ]; then
      ok=$((ok + 1))
      number park_time_s "$report" >> "$out/time"
      number position_error_m "$report" >> "$out/error"
    else
      echo "  $world seed $seed: not parked cleanly (log $log)" >&2
      cp "$log" "/tmp/autopark-$world-$seed.log"
    fi
    number mark "$report" >> "$out/mark"
    sed -n 's/.* in \([0-9.]*\) ms wall.*/\1/p' "$log" >> "$out/plan"
  done
  max_plan=$(sort -g "$out/plan" | tail -1)
  printf '| %s | %s | %d/%d | %s | %s | %s | %s | %s | %.2f |\n' "$world" "$algorithm" "$ok" "$total" \
    "$(median < "$out/mark")" "$(median < "$out/time")" "$(median < "$out/error")" "$(median < "$out/plan")" \
    "${max_plan:--}" "$(median < "$out/wall")"
done
rm -rf "$out"
