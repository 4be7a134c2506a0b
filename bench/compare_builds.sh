#!/usr/bin/env bash
# Two builds of Aula against each other on a shared, noisy machine: bench/exercise_overhead.sh on
# one build, then on the other, ROUNDS times in turn, so that the load of the moment weighs on
# both alike. Prints each build's whole runs (`aula run EXERCISE --headless`, per seed and round)
# and their median. BEFORE is usually a copy of build/bin, build/lib and build/share made before
# the change (`mkdir build-before && cp -a build/bin build/lib build/share build-before/`).
#   bench/compare_builds.sh BEFORE AFTER [ROUNDS] [SEEDS] [EXERCISES]
#   e.g. bench/compare_builds.sh build-before build 6 "1 2 3" teletaxi
set -euo pipefail
before="$1"
after="$2"
rounds="${3:-6}"
seeds="${4:-1 2 3}"
exercises="${5:-teletaxi}"
here="$(cd "$(dirname "$0")" && pwd)"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT

for round in $(seq 1 "$rounds"); do
  for build in "$before" "$after"; do
    # The per-seed rows of exercise_overhead.sh: exercise seed sim still moving whole /still /moving rtf.
    "$here/exercise_overhead.sh" "$build" "$seeds" "$exercises" 2>/dev/null |
      awk -v build="$build" 'NF == 9 && $2 ~ /^[0-9]+$/ {print build, $1, $6}' >> "$out"
  done
done
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
for exercise in $exercises; do
  for build in "$before" "$after"; do
    runs=$(awk -v b="$build" -v e="$exercise" '$1 == b && $2 == e {print $3}' "$out")
    printf '%-9s %-14s whole median %.3f s over %d runs:' "$exercise" "$build" "$(echo "$runs" | median)" \
      "$(echo "$runs" | wc -l)"
    echo "$runs" | sort -g | tr '\n' ' '
    echo
  done
done
