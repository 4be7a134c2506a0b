#!/usr/bin/env bash
# Closing the component's window as a window manager does (WM_DELETE_WINDOW) ends the run: the
# launcher says why, and the simulator and the referee end with it.
# Usage: test_close_window.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start close-window "$@"

"$build/bin/aula" run vacuum --algorithm=reference --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
find_window '^Vacuum cleaner referee$' >/dev/null
pgrep -f "aula-sim.*239.255.76.67:$port" >/dev/null || fail "no simulator running"
sleep 1
"$build/bin/aula-test-close-window" "$wid" || fail "could not send the close request"
wait_for 20 "the launcher to end" bash -c "! kill -0 $launcher"
set +e
wait $launcher
code=$?
set -e
grep -q "the component's window was closed: stopping the run" "$work/run.log" || fail "the terminal does not say why the run ended"
sleep 0.5
if pgrep -af "239.255.76.67:$port" | grep -v "pgrep"; then fail "processes left behind"; fi
echo "close window: the launcher ended (exit $code) and said so; no process left"
