#!/usr/bin/env bash
# Whole Autopark exercise, headless in lockstep (simulator + component + referee), over several
# seeds and slot sizes: success (parked, no collision), mark, sim time to park, distance to the
# ideal pose, the planner's wall time per plan() call and the wall time per run, with medians.
# Prints one Markdown table row per world.
#   bench/autopark_runs.sh [BUILD_DIR] [SEEDS] [ALGORITHM] [WORLDS]
#   e.g. bench/autopark_runs.sh build "$(seq -s' ' 1 20)" planner "autopark_ackermann_1.3L"
# WORLDS = "generated": streets the shipped ones are not, written by worlds/tools/make_autopark.py
# into a temporary folder: slots of 1.25, 1.4, 1.6 and 2.25 car lengths x curb offsets of 0, 0.5
# and 1.0 m, and a reversed start (facing -x), each with both cars (turning in place, car-like).
# One row per street and car: runs parked with no contact, declined (with the algorithm's
# reason), collided, and anything else (not parked, no reason).
set -euo pipefail
build="${1:-build}"
seeds="${2:-$(seq -s' ' 1 20)}"
algorithm="${3:-planner}"
worlds="${4:-autopark_ackermann_1.6L autopark_ackermann_1.4L autopark_ackermann_1.3L autopark_ackermann_1.2L autopark_ackermann autopark}"
out="$(mktemp -d)"
port=$(python3 "$(dirname "$0")/../tests/free_udp_port.py")
median() { sort -g | awk 'NF {a[++n]=$1} END {if (n == 0) print "-"; else if (n % 2) print a[(n+1)/2]; else print (a[n/2] + a[n/2+1]) / 2}'; }
number() { grep "\"$1\"" "$2" | head -1 | sed 's/.*: \(-\?[0-9.]*\).*/\1/'; }

if [ "$worlds" = "generated" ]; then
  make="$(dirname "$0")/../worlds/tools/make_autopark.py"
  echo "| street | car | parked, no contact | declined | collided | other | reason given |"
  echo "|---|---|---|---|---|---|---|"
  cells=()
  for slot in 5.0 5.6 6.4 9.0; do
    for curb in 0 0.5 1.0; do cells+=("$slot:$curb:-7,2.5,0"); done
  done
  cells+=("9.0:0:-7,2.5,3.14159")
  for cell in "${cells[@]}"; do
    IFS=: read -r slot curb start <<<"$cell"
    for car in diff ackermann; do
      world="$out/street.world"
      python3 "$make" --out "$world" --slot-length "$slot" --curb-offset "$curb" --kinematics "$car" --start="$start" >/dev/null
      parked=0 declined=0 collided=0 other=0 reason=""
      for seed in $seeds; do
        report="$out/r.json" log="$out/r.log"
        "$build/bin/aula" run autopark --headless --algorithm="$algorithm" --seed="$seed" --world="$world" \
          --report="$report" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$log" 2>&1 || true
        if [ "$(number collisions "$report")" != "0" ]; then
          collided=$((collided + 1)); cp "$log" "/tmp/autopark-collided-$slot-$curb-$car-$seed.log"
        elif grep -q '"parked": true' "$report"; then
          parked=$((parked + 1))
        elif grep -q "DECLINED" "$log"; then
          declined=$((declined + 1)); reason="$(grep -h 'DECLINED' "$log" | head -1 | sed 's/.* deg: //')"
        else
          other=$((other + 1)); cp "$log" "/tmp/autopark-other-$slot-$curb-$car-$seed.log"
        fi
      done
      total=$(wc -w <<<"$seeds")
      name="slot $slot m ($(echo "$slot / 4" | bc -l | xargs printf '%.2f') L), curb +$curb m"
      [ "$start" != "-7,2.5,0" ] && name="$name, reversed start"
      printf '| %s | %s | %d/%d | %d | %d | %d | %s |\n' "$name" "$car" "$parked" "$total" "$declined" "$collided" "$other" "$reason"
    done
  done
  rm -rf "$out"
  exit 0
fi
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
