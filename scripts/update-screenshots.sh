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

shoot vacuum Vacuum vacuum.world vacuum-cleaner vacuum-cleaner-referee --Vacuum.Algorithm=reference --screenshot-at=905
shoot teletaxi TeleTaxi cityLarge.world teletaxi teletaxi-referee --TeleTaxi.Algorithm=reference
shoot autopark Autopark autopark.world autopark autopark-referee --Autopark.Algorithm=planner --screenshot-at=120
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
echo "written: $out/{vacuum,teletaxi,autopark}_{component,referee}.png, $out/vacuum_python_fault_component.png, $out/crash-fault-panel.png: look at each"
