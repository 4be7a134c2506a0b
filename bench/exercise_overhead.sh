#!/usr/bin/env bash
# What the process boundaries cost: each exercise headless in lockstep (simulator + component +
# referee, `aula run EXERCISE --headless`) against the simulator alone (`aula-sim WORLD --rtf 0`,
# no clients) on the same world for the same sim time, publishing the same sensors. Runs alternate
# (whole, alone, whole, alone...) so a noisy machine weighs on both alike; the ratio is the figure.
# Then one more run of each under strace: the syscalls of the three processes, and the messages
# they handled (AULA_BUS_STATS: each Aula bus says how many it handled when it closes).
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

printf '%-9s %4s  %9s %9s %7s %8s %7s\n' exercise seed "sim(s)" "alone(s)" "whole(s)" ratio rtf
for exercise in $exercises; do
  algorithm="$(algorithm_of "$exercise")"
  world="$(world_of "$exercise")"
  : > "$out/$exercise.alone"; : > "$out/$exercise.whole"; : > "$out/$exercise.ratio"; : > "$out/$exercise.rtf"
  for seed in $seeds; do
    report="$out/$exercise-$seed.json"
    start=$(now)
    "$build/bin/aula" run "$exercise" --headless --algorithm="$algorithm" --seed="$seed" --report="$report" \
      --lcm-url="$url" >/dev/null 2>&1
    whole=$(echo "$(now) - $start" | bc -l)
    sim_s=$(field "$report" sim_time_s)
    start=$(now)
    "$build/bin/aula-sim" "$world" --duration "$sim_s" --rtf 0 --seed "$seed" --lcm-url "$url" >/dev/null 2>&1
    alone=$(echo "$(now) - $start" | bc -l)
    ratio=$(echo "$whole / $alone" | bc -l)
    rtf=$(echo "$sim_s / $whole" | bc -l)
    printf '%-9s %4s  %9.1f %9.3f %7.3f %8.2f %7.0f\n' "$exercise" "$seed" "$sim_s" "$alone" "$whole" "$ratio" "$rtf"
    echo "$alone" >> "$out/$exercise.alone"; echo "$whole" >> "$out/$exercise.whole"
    echo "$ratio" >> "$out/$exercise.ratio"; echo "$rtf" >> "$out/$exercise.rtf"
  done
done
echo
printf '%-9s  %-17s %-17s %-15s %s\n' exercise "alone min/median" "whole min/median" "ratio min/med" "real-time factor (median)"
for exercise in $exercises; do
  printf '%-9s  %6.3f / %6.3f s  %6.3f / %6.3f s  %5.2f / %5.2f   %.0fx\n' "$exercise" \
    "$(minimum < "$out/$exercise.alone")" "$(median < "$out/$exercise.alone")" \
    "$(minimum < "$out/$exercise.whole")" "$(median < "$out/$exercise.whole")" \
    "$(minimum < "$out/$exercise.ratio")" "$(median < "$out/$exercise.ratio")" "$(median < "$out/$exercise.rtf")"
done

if command -v strace >/dev/null; then
  echo
  printf '%-9s %9s %9s %9s %9s  %s\n' exercise sendmsg recvmsg handled "recv/handled" "(one run, seed $(echo "$seeds" | awk '{print $1}'), under strace)"
  for exercise in $exercises; do
    seed=$(echo "$seeds" | awk '{print $1}')
    AULA_BUS_STATS=1 strace -f -c -e trace=sendmsg,recvmsg,recvfrom -o "$out/$exercise.strace" \
      "$build/bin/aula" run "$exercise" --headless --algorithm="$(algorithm_of "$exercise")" --seed="$seed" \
      --report="$out/$exercise-strace.json" --lcm-url="$url" >/dev/null 2>"$out/$exercise.stats"
    sent=$(awk '$NF=="sendmsg" {print $4}' "$out/$exercise.strace")
    received=$(awk '$NF=="recvmsg" || $NF=="recvfrom" {s += $4} END {print s + 0}' "$out/$exercise.strace")
    handled=$(grep -o 'handled [0-9]* messages' "$out/$exercise.stats" | awk '{s += $2} END {print s + 0}')
    printf '%-9s %9s %9s %9s %9.2f\n' "$exercise" "$sent" "$received" "$handled" "$(echo "$received / $handled" | bc -l)"
  done
fi
