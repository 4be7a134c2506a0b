#!/usr/bin/env bash
# Refreshes the windows' pictures in docs/images (<exercise>_component.png, <exercise>_referee.png)
# from the current build: each exercise's reference algorithm, autostarted, under a virtual
# display, in lockstep as fast as possible. The referee's window is grabbed when it ends the
# episode, the component's a few sim seconds later (it then shows how the referee ended it).
# Look at each picture before committing it.
# Usage: scripts/update-screenshots.sh [BUILD_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
out="$root/docs/images"
if [ -z "${AULA_SCREENSHOT_DISPLAY:-}" ]; then
  AULA_SCREENSHOT_DISPLAY=1 exec xvfb-run -a -s "-screen 0 1600x1100x24" bash "$0" "$build"
fi

# shoot NAME SECTION WORLD COMPONENT REFEREE [COMPONENT_ARGS...]: NAME_component.png, NAME_referee.png
shoot() {
  local exercise="$1" section="$2" world="$3" component="$4" referee="$5"
  shift 5
  local url="udpm://239.255.76.67:$((20000 + RANDOM % 20000))?ttl=0"
  echo "== $exercise"
  "$build/bin/aula-sim" "$build/share/aula/worlds/$world" --lockstep --Simulator.Lockstep.WaitForClients=2 --rtf=0 \
    --lcm-url="$url" &
  local sim=$!
  "$build/bin/$referee" --lcm-url="$url" --screenshot="$out/${exercise}_referee.png" &
  local ref=$!
  "$build/bin/$component" --lcm-url="$url" "--$section.Autostart=true" --screenshot="$out/${exercise}_component.png" "$@"
  wait "$ref" || true
  kill -TERM "$sim"
  wait "$sim" || true
}

# Each exercise's pictures as it declares them (SCREENSHOT of its aula_exercise()).
shot=()
while read -r line <&3; do  # fd 3: the programs keep the script's stdin
  case "$line" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086  # the declared arguments, one word each
  shoot $line
  shot+=("${line%% *}")
done 3<"$build/exercises/screenshots.txt"
# A student's MyAlgorithm.py that divides by zero on its 31st call: the traceback in the fault panel.
shoot vacuum_python_fault Vacuum vacuum.world vacuum-cleaner vacuum-cleaner-referee \
  --Vacuum.Algorithm="$root/tests/data/python/raises/MyAlgorithm.py" --screenshot-at=6
rm -f "$out/vacuum_python_fault_referee.png"  # the component's fault panel is the point
# A student's C++ plugin that writes through a null pointer on its 6th call: with windows the
# crash is the fault, named at its line, and the window stays.
shoot crash_fault_panel Vacuum vacuum.world vacuum-cleaner vacuum-cleaner-referee \
  --Vacuum.Algorithm="$build/tests/integration/plugins/libaula_test_fault_segfault.so" --screenshot-at=3
mv "$out/crash_fault_panel_component.png" "$out/crash-fault-panel.png"
rm -f "$out/crash_fault_panel_referee.png"
echo "written: $out/{$(IFS=,; echo "${shot[*]}")}_{component,referee}.png, $out/vacuum_python_fault_component.png, $out/crash-fault-panel.png: look at each"
