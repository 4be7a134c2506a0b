#!/usr/bin/env bash
# `./aula run EXERCISE` builds aula_run_<EXERCISE>: its dependency graph (ninja's own) must hold
# that exercise's student file and no other exercise's code, so a compile error in one exercise's
# student file never stops another exercise from running. The one exception is each exercise's
# declaration (components/<other>/exercise.cpp: its settings tables), which every program's
# settings library holds so that `aula` lists and checks every exercise.
# Usage: test_build_what_is_run.sh BUILD_DIR
set -euo pipefail
build="$1"
mapfile -t exercises < <(ninja -C "$build" -t targets all | sed -n 's/^aula_run_\([a-z0-9_]*\): phony$/\1/p' | grep -vx demo | sort -u)
[ "${#exercises[@]}" -ge 3 ] || { echo "FAIL: fewer than three aula_run_<exercise> targets: ${exercises[*]}"; exit 1; }
for exercise in "${exercises[@]}"; do
  inputs="$(ninja -C "$build" -t inputs "aula_run_$exercise")"
  grep -q "components/$exercise/student/MyAlgorithm.cpp" <<<"$inputs" \
    || { echo "FAIL: aula_run_$exercise does not build $exercise's student file"; exit 1; }
  for other in "${exercises[@]}"; do
    [ "$other" = "$exercise" ] && continue
    foreign="$(grep -E "(components|referees)/$other/" <<<"$inputs" | grep -v "components/$other/exercise.cpp" || true)"
    if [ -n "$foreign" ]; then
      echo "FAIL: aula_run_$exercise builds $other's code:"; head <<<"$foreign"; exit 1
    fi
  done
done
echo "each aula_run_<exercise> builds its own exercise only (${exercises[*]})"
