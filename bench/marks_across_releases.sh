#!/usr/bin/env bash
# The references' marks over seeds, one line per run, to compare two Debian releases (issue 40):
# physics libraries differ between them (DART 6.12 / 6.13), so the same seed may drive otherwise.
# Run it on each release and diff the outputs (scripts/ci-debian13.sh --marks=SEEDS runs it in
# the Debian 13 root).
# Usage: bench/marks_across_releases.sh BUILD_DIR [SEEDS=1-5]
set -euo pipefail
build="$(cd "$1" && pwd)"; seeds="${2:-1-5}"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-marks-XXXXXX")"
trap 'rm -rf "$work"' EXIT
first="${seeds%-*}"; last="${seeds#*-}"
for spec in "vacuum reference coverage_percent" "teletaxi reference final_distance_m" \
            "autopark reactive park_time_s" "autopark planner park_time_s"; do
  read -r exercise algorithm measure <<<"$spec"
  for seed in $(seq "$first" "$last"); do
    "$build/bin/aula" run "$exercise" --headless --algorithm="$algorithm" --seed="$seed" --report="$work/r.json" \
      >"$work/run.log" 2>&1 || true
    python3 - "$work/r.json" "$exercise" "$algorithm" "$seed" "$measure" <<'PY'
import json, sys
path, exercise, algorithm, seed, measure = sys.argv[1:]
try:
    r = json.load(open(path))
    print(f"{exercise:9} {algorithm:9} seed {seed}: mark {r['mark']:.2f}  {measure} {r.get(measure, float('nan')):.3f}")
except (OSError, ValueError, KeyError) as e:
    print(f"{exercise:9} {algorithm:9} seed {seed}: no report ({e})")
PY
    rm -f "$work/r.json"
  done
done
