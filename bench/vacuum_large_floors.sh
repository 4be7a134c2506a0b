#!/usr/bin/env bash
# The vacuum reference on houses larger than an episode lets it sweep: its coverage and which
# rooms it entered, and when (docs/performance.md, "Large floors"). Extra arguments go to `aula run`.
#   bench/vacuum_large_floors.sh [BUILD_DIR] [SEEDS] [AULA RUN OPTIONS...]
#   e.g. bench/vacuum_large_floors.sh build "1 2 3" --Simulator.Noise=realistic
set -euo pipefail
. "$(dirname "$0")/house_bench.sh"
# name | make_house.py arguments
houses=(
  "l127-3x2|--seed 78 --rooms-x 3 --rooms-y 2 --room-size 5.0 --furniture 3"
  # Drawn after the work of 2026-11-29 (session 28) and held out of it.
  "l116-3x2-held|--seed 91 --rooms-x 3 --rooms-y 2 --room-size 5.0 --furniture 3"
  "l124-4x3-held|--seed 606 --rooms-x 4 --rooms-y 3 --room-size 3.8 --door-width 0.8 --furniture 2"
)
printf '| house | make_house.py arguments | floor | seed | coverage | rooms entered (first visits, s) |\n|---|---|---|---|---|---|\n'
for entry in "${houses[@]}"; do
  name="${entry%%|*}"
  args="${entry#*|}"
  house "$name" "$args"
  for seed in $seeds; do
    report="$out/$name-$seed.json"
    trace="$out/$name-$seed.trace.json"
    run_reference "$out/$name.world" "$seed" "$report" --trace="$trace" "$@"
    rooms="$(python3 "$here/bench/vacuum_rooms.py" "$out/$name.world" "$trace")"
    printf '| %s | `%s` | %.1f m² | %s | %.1f %% | %s |\n' "$name" "$args" "$(field floor_area_m2 "$report")" "$seed" \
      "$(field coverage_percent "$report")" "$rooms"
  done
done
