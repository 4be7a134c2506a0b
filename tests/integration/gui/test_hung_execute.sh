#!/usr/bin/env bash
# An execute() that never returns, with windows (the endless-loop plugin, a 1 s budget, in
# lockstep): the component does not end (exit 3 is for headless runs); it says so in the log,
# stops the robot and keeps acknowledging its ticks, so the simulator goes on; the referee ends
# the grading with the reason; the window still answers: closing it ends the run.
# Usage: test_hung_execute.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start hung-execute "$@"
plugin="$build/tests/integration/plugins/libaula_test_fault_endless_loop.so"
[ -f "$plugin" ] || fail "no endless-loop plugin at $plugin"

"$build/bin/aula-test-lcm-probe" "$url" 120 >"$work/bus.log" &
probe=$!
"$build/bin/aula" run vacuum --algorithm="$plugin" --Vacuum.Autostart=true --Component.ExecuteBudget=1 --lockstep \
  --rtf=2 --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
wait_for 30 "the component to say execute() hung" grep -q "execute() used more than 1 s of CPU time" "$work/run.log"
last_clock() { grep '^CLOCK' "$work/bus.log" | tail -n1; }
hung_at=$(last_clock)
sleep 4
now=$(last_clock)
pgrep -f "vacuum-cleaner .*239.255.76.67:$port" >/dev/null || fail "the component ended"
# In lockstep the simulator steps only when the component acknowledges: 4 wall s at 2x.
advanced=$(awk -v a="$(echo "$hung_at" | awk '{ print $3 }')" -v b="$(echo "$now" | awk '{ print $3 }')" 'BEGIN { print b - a }')
awk -v d="$advanced" 'BEGIN { exit !(d > 4) }' || fail "the simulator advanced $advanced sim s in 4 wall s after the hang"
grep -q "dropped: no ack" "$work/run.log" && fail "the simulator dropped a client"
# The robot stopped: it drove at 0.3 m/s before the hang; from 1 wall s after, it stands still.
moved=$(awk -v from="$(echo "$hung_at" | awk '{ print $2 + 1 }')" '/^POSE ROOMBA_POSE/ && $3 >= from {
          if (!n++) { x0 = $5; y0 = $6 } x = $5; y = $6 } END { printf "%.3f\n", n ? sqrt((x - x0)^2 + (y - y0)^2) : -1 }' "$work/bus.log")
awk -v m="$moved" 'BEGIN { exit !(m >= 0 && m < 0.02) }' || fail "the robot moved $moved m after the hang"
wait_for 10 "the referee's report with the reason" grep -q '"algorithm_error": "execute() used more than 1 s of CPU time' "$work/r.json"
grep -q '"finished": false' "$work/r.json" || fail "the report does not say the run ended early"
"$build/bin/aula-test-close-window" "$wid" || fail "could not send the close request"
wait_for 20 "the launcher to end after the window was closed" bash -c "! kill -0 $launcher"
grep -q "the component's window was closed: stopping the run" "$work/run.log" || fail "the window did not close the run"
kill -TERM $probe
sleep 0.5
if pgrep -af "239.255.76.67:$port"; then fail "processes left behind"; fi
echo "hung execute(): the window stayed, the simulator advanced $advanced sim s in 4 s, the robot moved $moved m after"
