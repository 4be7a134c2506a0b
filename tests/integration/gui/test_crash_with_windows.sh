#!/usr/bin/env bash
# The component dying with windows (the segfault plugin) ends the whole run: the referee's window
# grades what there is, writes the report with the reason and ends, and the launcher stops the
# simulator. Before, the simulator and the referee ran on with the countdown moving.
# Usage: test_crash_with_windows.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start crash-with-windows "$@"
plugin="$build/tests/integration/plugins/libaula_test_fault_segfault.so"
[ -f "$plugin" ] || fail "no segfault plugin at $plugin"

"$build/bin/aula" run vacuum --algorithm="$plugin" --Vacuum.Autostart=true --report="$work/r.json" \
  --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
find_window '^Vacuum cleaner referee$' >/dev/null
wait_for 30 "the launcher to end after the crash" bash -c "! kill -0 $launcher"
grep -q "component crashed (SIGSEGV)" "$work/run.log" || fail "the terminal does not say the component crashed"
grep -q '"aborted": "component crashed (SIGSEGV)"' "$work/r.json" || fail "the report does not say why the run ended"
grep -q '"finished": false' "$work/r.json" || fail "the report does not say the run ended early"
sleep 0.5
if pgrep -af "239.255.76.67:$port" | grep -v "pgrep"; then fail "processes left behind"; fi
echo "a crash with windows ended the run; the report says why"
