#!/usr/bin/env bash
# What the process boundaries cost: each exercise headless in lockstep (simulator + component +
# referee, `aula run EXERCISE --headless`) against the simulator alone (`aula-sim WORLD --rtf 0`,
# no clients) on the same world for the same sim time, publishing the same sensors, two ways:
#   still:  the robots never move (no commands), the issue's first baseline;
#   moving: the robots make the run's own motions (`aula-sim --commands=RUN.lcmlog`: the motors
#           commands recorded in that run, each at the tick it answered), so the physics does the
#           same work as in the whole exercise (contacts, the solver) and the ratio is the process
#           boundaries alone.
# Runs alternate (whole, still, moving, ...) so a noisy machine weighs on all alike; the ratios
# are the figures. Each seed's run is recorded once first, untimed. Then one more run of each
# exercise under strace: the syscalls of the three processes, and the messages they handled
# (AULA_BUS_STATS: each Aula bus says how many it handled when it closes).
#   bench/exercise_overhead.sh [BUILD_DIR] [SEEDS] [EXERCISES]
#   e.g. bench/exercise_overhead.sh build "1 2 3" "vacuum teletaxi autopark"
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
seeds="${2:-1 2 3}"
exercises="${3:-vacuum teletaxi autopark}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$((20000 + $$ % 20000))
url="udpm://239.255.76.67:$port?ttl=0"

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
minimum() { sort -g | head -1; }
now() { date +%s.%N; }
field() { grep "\"$2\"" "$1" | head -1 | sed 's/.*: *\([-0-9.e]*\).*/\1/'; }

algorithm_of() { case "$1" in autopark) echo planner ;; *) echo reference ;; esac; }
world_of() { "$build/bin/aula" config "$1" 2>/dev/null | awk '/^world: / {print $2; exit}'; }

printf '%-9s %4s  %7s %9s %9s %8s %8s %8s %6s\n' exercise seed "sim(s)" "still(s)" "moving(s)" "whole(s)" "/still" "/moving" rtf
for exercise in $exercises; do
  algorithm="$(algorithm_of "$exercise")"
  world="$(world_of "$exercise")"
  for f in still moving whole ratio_still ratio_moving rtf; do : > "$out/$exercise.$f"; done
  for seed in $seeds; do
    report="$out/$exercise-$seed.json"
    record="$out/$exercise-$seed.lcmlog"
    "$build/bin/aula" run "$exercise" --headless --algorithm="$algorithm" --seed="$seed" --report="$out/recorded.json" \
      --record="$record" --lcm-url="$url" >/dev/null 2>&1
    start=$(now)
    "$build/bin/aula" run "$exercise" --headless --algorithm="$algorithm" --seed="$seed" --report="$report" \
      --lcm-url="$url" >/dev/null 2>&1
    whole=$(echo "$(now) - $start" | bc -l)
    cmp -s "$report" "$out/recorded.json" || echo "warning: $exercise seed $seed: the recorded run's report differs" >&2
    sim_s=$(field "$report" sim_time_s)
    # The lone simulator steps as the exercise's run did (aula run gives it the exercise's step).
    step_s=$("$build/bin/aula" config "$exercise" | awk '$1 == "Simulator.PhysicsStep" {print $3}')
    start=$(now)
    "$build/bin/aula-sim" "$world" --duration "$sim_s" --rtf 0 --seed "$seed" --Simulator.PhysicsStep="$step_s" \
      --lcm-url "$url" >/dev/null 2>&1
    still=$(echo "$(now) - $start" | bc -l)
    start=$(now)
    "$build/bin/aula-sim" "$world" --duration "$sim_s" --rtf 0 --seed "$seed" --Simulator.PhysicsStep="$step_s" \
      --lcm-url "$url" --commands="$record" >/dev/null 2>&1
    moving=$(echo "$(now) - $start" | bc -l)
    ratio_still=$(echo "$whole / $still" | bc -l)
    ratio_moving=$(echo "$whole / $moving" | bc -l)
    rtf=$(echo "$sim_s / $whole" | bc -l)
    printf '%-9s %4s  %7.1f %9.3f %9.3f %8.3f %8.2f %8.2f %6.0f\n' "$exercise" "$seed" "$sim_s" "$still" "$moving" "$whole" \
      "$ratio_still" "$ratio_moving" "$rtf"
    echo "$still" >> "$out/$exercise.still"; echo "$moving" >> "$out/$exercise.moving"; echo "$whole" >> "$out/$exercise.whole"
    echo "$ratio_still" >> "$out/$exercise.ratio_still"; echo "$ratio_moving" >> "$out/$exercise.ratio_moving"
    echo "$rtf" >> "$out/$exercise.rtf"
  done
done
echo
printf '%-9s  %-17s %-17s %-17s %-15s %-15s %s\n' exercise "still min/median" "moving min/median" "whole min/median" \
  "/still min/med" "/moving min/med" "real-time factor (median)"
mm() { printf '%6.3f / %6.3f s' "$(minimum < "$1")" "$(median < "$1")"; }
rr() { printf '%5.2f / %5.2f' "$(minimum < "$1")" "$(median < "$1")"; }
for exercise in $exercises; do
  printf '%-9s  %s  %s  %s  %s   %s   %.0fx\n' "$exercise" "$(mm "$out/$exercise.still")" "$(mm "$out/$exercise.moving")" \
    "$(mm "$out/$exercise.whole")" "$(rr "$out/$exercise.ratio_still")" "$(rr "$out/$exercise.ratio_moving")" \
    "$(median < "$out/$exercise.rtf")"
done

if command -v strace >/dev/null; then
  echo
  printf '%-9s %9s %9s %9s %9s %9s  %s\n' exercise sendmsg "recv*" datagrams handled "dgram/msg" \
    "(one run, seed $(echo "$seeds" | awk '{print $1}'), under strace; recv* = recvmsg+recvfrom+recvmmsg calls)"
  for exercise in $exercises; do
    seed=$(echo "$seeds" | awk '{print $1}')
    AULA_BUS_STATS=1 strace -f -c -e trace=sendmsg,recvmsg,recvfrom,recvmmsg -o "$out/$exercise.strace" \
      "$build/bin/aula" run "$exercise" --headless --algorithm="$(algorithm_of "$exercise")" --seed="$seed" \
      --report="$out/$exercise-strace.json" --lcm-url="$url" >/dev/null 2>"$out/$exercise.stats"
    sent=$(awk '$NF=="sendmsg" {print $4}' "$out/$exercise.strace")
    received=$(awk '$NF=="recvmsg" || $NF=="recvfrom" || $NF=="recvmmsg" {s += $4} END {print s + 0}' "$out/$exercise.strace")
    handled=$(grep -o 'handled [0-9]* messages' "$out/$exercise.stats" | awk '{s += $2} END {print s + 0}')
    datagrams=$(grep -o 'of [0-9]* datagrams' "$out/$exercise.stats" | awk '{s += $2} END {print s + 0}')
    printf '%-9s %9s %9s %9s %9s %9.2f\n' "$exercise" "$sent" "$received" "$datagrams" "$handled" \
      "$(echo "$datagrams / $handled" | bc -l)"
  done
fi
