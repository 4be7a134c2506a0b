#!/usr/bin/env bash
# Closing the TeleTaxi window (the window manager's close) while its "Grid Field" window is open
# ends the whole run: the component, the simulator and the referee. Qt by itself quit only when
# the last window closed, so the three ran on behind the grid's window.
# Usage: test_close_with_grid_window.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start close-with-grid "$@"
plugin="$build/tests/integration/plugins/libaula_test_fault_teletaxi_shows_grid.so"
[ -f "$plugin" ] || fail "no grid-showing plugin at $plugin"

"$build/bin/aula" run teletaxi --algorithm="$plugin" --TeleTaxi.Autostart=true --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^TeleTaxi - Gradient Path Planning$')
find_window '^Grid Field$' >/dev/null
find_window '^TeleTaxi referee$' >/dev/null
for program in aula-sim teletaxi teletaxi-referee; do
  pgrep -f "$program .*239.255.76.67:$port" >/dev/null || fail "no $program running"
done
"$build/bin/aula-test-close-window" "$wid" || fail "could not send the close request"
wait_for 20 "the launcher to end" bash -c "! kill -0 $launcher"
grep -q "the component's window was closed: stopping the run" "$work/run.log" || fail "the terminal does not say why the run ended"
sleep 0.5
if pgrep -af "239.255.76.67:$port" | grep -v "pgrep"; then fail "processes left behind"; fi
echo "closing the TeleTaxi window with the grid's open ended all three processes"
