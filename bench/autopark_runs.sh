#!/usr/bin/env bash
# Whole Autopark exercise, headless in lockstep (simulator + component + referee), over several
# seeds and slot sizes: success (parked, no collision), mark, sim time to park, distance to the
# ideal pose, the planner's wall time per plan() call and the wall time per run, with medians.
# Prints one Markdown table row per world.
#   bench/autopark_runs.sh [BUILD_DIR] [SEEDS] [ALGORITHM] [WORLDS]
#   e.g. bench/autopark_runs.sh build "$(seq -s' ' 1 20)" planner "autopark_ackermann_1.3L"
# WORLDS = "generated": streets the shipped ones are not, written by worlds/tools/make_autopark.py
# into a temporary folder: slots of 1.25, 1.3, 1.4, 1.6 and 2 car lengths x curb offsets of 0, 0.5
# and 1 m x a forward and a reversed start (facing away from the slot), each with both cars
# (turning in place, car-like). One row per slot, start and car, over the three curb offsets and
# the seeds: runs parked with no contact, declined (with the algorithm's reason), collided, any
# other end (not parked, no reason), and runs whose car left the street (the referee's
# "left_street"); the worst cell (curb offset) of the row.
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
  echo "| slot | start | car | parked, no contact | declined | collided | other | left the street | worst curb offset | reason given |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for k in 1.25 1.3 1.4 1.6 2; do
    slot=$(echo "$k * 4" | bc -l | xargs printf '%.2f')
    for start in forward reversed; do
      for car in diff ackermann; do
        parked=0 declined=0 collided=0 other=0 left=0 total=0 reason="" worst="" worst_parked=999
        for curb in 0 0.5 1; do
          world="$out/street.world"
          flags=(--out "$world" --slot-length "$slot" --curb-offset "$curb" --kinematics "$car")
          [ "$start" = reversed ] && flags+=(--reversed)
          python3 "$make" "${flags[@]}" >/dev/null
          cell_parked=0
          for seed in $seeds; do
            report="$out/r.json" log="$out/r.log"
            rm -f "$report"
            nice -n 10 "$build/bin/aula" run autopark --headless --algorithm="$algorithm" --seed="$seed" --world="$world" \
              --report="$report" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$log" 2>&1 || true
            total=$((total + 1))
            tag="$algorithm-$k-$start-$car-$curb-$seed"
            grep -q '"left_street": true' "$report" && left=$((left + 1)) && cp "$log" "/tmp/autopark-left-$tag.log"
            if [ "$(number collisions "$report")" != "0" ]; then
              collided=$((collided + 1)); cp "$log" "/tmp/autopark-collided-$tag.log"
            elif grep -q '"parked": true' "$report"; then
              parked=$((parked + 1)); cell_parked=$((cell_parked + 1))
            elif grep -qE "DECLINED|FAILED" "$log"; then
              declined=$((declined + 1)); reason="$(grep -hE 'DECLINED|FAILED' "$log" | head -1 | sed 's/.* deg: //')"
            else
              other=$((other + 1)); cp "$log" "/tmp/autopark-other-$tag.log"
            fi
          done
          [ "$cell_parked" -lt "$worst_parked" ] && worst_parked=$cell_parked && worst="+$curb m: $cell_parked/$(wc -w <<<"$seeds")"
        done
        printf '| %s m (%s L) | %s | %s | %d/%d | %d | %d | %d | %d | %s | %s |\n' "$slot" "$k" "$start" "$car" "$parked" "$total" \
          "$declined" "$collided" "$other" "$left" "$worst" "$reason"
      done
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
