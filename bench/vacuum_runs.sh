#!/usr/bin/env bash
# Whole vacuum-cleaner exercise, headless in lockstep (simulator + component + referee), over
# several seeds: wall time per run, coverage and mark per algorithm, with medians. Extra
# arguments go to `aula run` (e.g. --Vacuum.Referee.Rubric=original for the thesis's marks).
#   bench/vacuum_runs.sh [BUILD_DIR] [SEEDS] [ALGORITHMS] [AULA RUN OPTIONS...]
#   e.g. bench/vacuum_runs.sh build "1 2 3 4 5 6 7 8 9 10" "reference bounce"
set -euo pipefail
build="${1:-build}"
seeds="${2:-1 2 3 4 5 6 7 8 9 10}"
algorithms="${3:-reference bounce}"
shift $(( $# < 3 ? $# : 3 ))
out="$(mktemp -d)"
port=$((20000 + $$ % 20000))
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
p10() { sort -g | awk '{a[NR]=$1} END {i = int(NR * 0.1 + 0.999999); if (i < 1) i = 1; print a[i]}'; }
for algorithm in $algorithms; do
  : > "$out/$algorithm.coverage"
  : > "$out/$algorithm.wall"
  : > "$out/$algorithm.mark"
  for seed in $seeds; do
    start=$(date +%s.%N)
    "$build/bin/aula" run vacuum --headless --algorithm="$algorithm" --seed="$seed" \
      --report="$out/$algorithm-$seed.json" --lcm-url="udpm://239.255.76.67:$port?ttl=0" "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    wall=$(echo "$end - $start" | bc -l)
    coverage=$(grep '^  "coverage_percent"' "$out/$algorithm-$seed.json" | sed 's/.*: \([0-9.]*\),/\1/')
    mark=$(grep '^  "mark"' "$out/$algorithm-$seed.json" | sed 's/.*: \([0-9.]*\),/\1/')
    printf '%-9s seed %2s  coverage %6.2f %%  mark %5.2f  wall %5.2f s\n' "$algorithm" "$seed" "$coverage" "$mark" "$wall"
    echo "$coverage" >> "$out/$algorithm.coverage"
    echo "$mark" >> "$out/$algorithm.mark"
    echo "$wall" >> "$out/$algorithm.wall"
  done
  printf '%-9s median coverage %.2f %%, p10 %.2f %%, median mark %.2f, median wall %.2f s over seeds: %s\n' "$algorithm" \
    "$(median < "$out/$algorithm.coverage")" "$(p10 < "$out/$algorithm.coverage")" "$(median < "$out/$algorithm.mark")" \
    "$(median < "$out/$algorithm.wall")" "$seeds"
done
rm -rf "$out"
