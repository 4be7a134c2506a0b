#!/usr/bin/env bash
# A program in RoboticsAcademy's shape with windows (issue 41): its calls run on the window's
# AlgorithmThread (lockstep, so that the program sees what it sees headless), a thread Python did not start, whose Python thread state must outlive each
# call (the paused program is a greenlet of that state). With Autostart it finds the slot; Ctrl+R
# while it runs ends the paused program and starts it again from its top, in the same simulator,
# and it parks; what it printed is in the component's output.
# Usage: test_ra_program_with_windows.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start ra-program "$@"
program="$(cd "$(dirname "$0")/../../data/python/ra_autopark" && pwd)/MyAlgorithm.py"

"$build/bin/aula" run autopark --algorithm="$program" --Autopark.Autostart=true --lockstep --rtf=4 \
  --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Autopark$')
wait_for 60 "the program to find the slot" grep -q "slot found" "$work/run.log"
xdotool windowfocus --sync "$wid"
xdotool key --clearmodifiers ctrl+r
wait_for 90 "the program, started again, to find the slot" bash -c "[ \$(grep -c 'slot found' '$work/run.log') -ge 2 ]"
wait_for 90 "the program to park" grep -q "parked at (" "$work/run.log"
wait_for 60 "the report of the reloaded episode" grep -q '"reloads": 1' "$work/r.json"
grep -q '"parked": true' "$work/r.json" || fail "the referee did not see it parked: $(cat "$work/r.json")"
grep -q "crashed" "$work/run.log" && fail "the component crashed"
kill -TERM $launcher
wait $launcher || true
echo "a RoboticsAcademy program with windows: found the slot, reloaded mid-run, parked"
