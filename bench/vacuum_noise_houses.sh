#!/usr/bin/env bash
# The vacuum reference (the mapping cleaner, calibration's anchor) on generated houses of
# different door widths and floor sizes, with and without sensor noise: median coverage over the
# seeds, and the most bumps and time stuck of any run (docs/performance.md, "The vacuum reference
# under noise"). Extra arguments go to `aula run`.
#   bench/vacuum_noise_houses.sh [BUILD_DIR] [SEEDS] [AULA RUN OPTIONS...]
#   e.g. bench/vacuum_noise_houses.sh build "1 2 3"
set -euo pipefail
. "$(dirname "$0")/house_bench.sh"
# name | make_house.py arguments
houses=(
  "d06-4x3-issue|--seed 101 --rooms-x 4 --rooms-y 3 --door-width 0.6 --furniture 2"
  "d06-4x3|--seed 202 --rooms-x 4 --rooms-y 3 --door-width 0.6 --furniture 2"
  "d06-3x2|--seed 31 --rooms-x 3 --rooms-y 2 --door-width 0.6 --furniture 2"
  "d07-4x2|--seed 44 --rooms-x 4 --rooms-y 2 --room-size 2.8 --door-width 0.7"
  "d09-3x2-large|--seed 21 --rooms-x 3 --rooms-y 2 --room-size 4.4 --furniture 2"
  "d08-3x3|--seed 57 --rooms-x 3 --rooms-y 3 --room-size 3.6 --door-width 0.8 --furniture 3"
  # Drawn after the work of 2026-11-29 and held out of it.
  "d06-4x3-held|--seed 303 --rooms-x 4 --rooms-y 3 --door-width 0.6 --furniture 2"
  "d06-3x3-held|--seed 404 --rooms-x 3 --rooms-y 3 --door-width 0.6 --furniture 2"
)
median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2] + a[NR/2+1]) / 2}'; }
printf '| house | make_house.py arguments | floor | coverage, no noise | coverage, realistic noise | most bumps, stuck (noise) |\n|---|---|---|---|---|---|\n'
for entry in "${houses[@]}"; do
  name="${entry%%|*}"
  args="${entry#*|}"
  house "$name" "$args"
  row=()
  floor=""
  for noise in off realistic; do
    : > "$out/$name-$noise.coverage"
    bumps=0
    stuck=0
    for seed in $seeds; do
      report="$out/$name-$noise-$seed.json"
      run_reference "$out/$name.world" "$seed" "$report" --Simulator.Noise="$noise" "$@"
      field coverage_percent "$report" >> "$out/$name-$noise.coverage"
      floor="$(field floor_area_m2 "$report")"
      bumps=$(( $(field bumps "$report") > bumps ? $(field bumps "$report") : bumps ))
      stuck=$(awk -v a="$(field stuck_s "$report")" -v b="$stuck" 'BEGIN {print (a > b ? a : b)}')
    done
    row+=("$(printf '%.1f %%' "$(median < "$out/$name-$noise.coverage")")")
  done
  printf '| %s | `%s` | %.1f m² | %s | %s | %s, %s s |\n' "$name" "$args" "$floor" "${row[0]}" "${row[1]}" "$bumps" "$stuck"
done
echo "seeds: $seeds; medians over them"
