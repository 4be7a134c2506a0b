#!/usr/bin/env bash
# `./aula run EXERCISE` builds aula_run_<EXERCISE>: its dependency graph (ninja's own) must hold
# that exercise's student file and no other exercise's, so a compile error in one exercise's
# student file never stops another exercise from running.
# Usage: test_build_what_is_run.sh BUILD_DIR
set -euo pipefail
build="$1"
for exercise in vacuum teletaxi autopark; do
  inputs="$(ninja -C "$build" -t inputs "aula_run_$exercise")"
  grep -q "components/$exercise/student/MyAlgorithm.cpp" <<<"$inputs" \
    || { echo "FAIL: aula_run_$exercise does not build $exercise's student file"; exit 1; }
  for other in vacuum teletaxi autopark; do
    [ "$other" = "$exercise" ] && continue
    if grep -q "components/$other/" <<<"$inputs"; then
      echo "FAIL: aula_run_$exercise builds $other's code:"; grep "components/$other/" <<<"$inputs" | head; exit 1
    fi
  done
done
echo "each aula_run_<exercise> builds its own exercise only"
