#!/usr/bin/env bash
# Hot reload of a student's MyAlgorithm.py, the way a student does it, under a virtual display
# driven with xdotool: windows open on a file that stands still; the student saves a version
# with a syntax error and presses Ctrl+R: the component stays up and says the line; the student
# fixes it to drive at 0.3 m/s, saves, and presses Run (F5), which reloads the new version
# first. It runs without restarting the simulator or the referee: the referee grades the last
# episode ("reloads": 2), in which the robot moved from its start. Nothing is compiled.
# Usage: test_python_hot_reload.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start python-hot-reload "$@"

mkdir "$work/student"
# version SPEED [broken]: the student's file, driving at SPEED m/s; "broken" drops a colon (line 8).
version() {
  local colon=":"
  [ "${2:-}" = broken ] && colon=""
  cat >"$work/student/MyAlgorithm.py.new" <<PY
SPEED = $1  # m/s


class MyAlgorithm:
    def __init__(self, seed):
        print(f"python: drives at {SPEED:.2f} m/s", flush=True)

    def execute(self, api)$colon
        api.motors.sendV(SPEED)
        api.motors.sendW(0.0)
PY
  mv "$work/student/MyAlgorithm.py.new" "$work/student/MyAlgorithm.py"  # as an editor saves
}
version 0.0
"$build/bin/aula" run vacuum --algorithm="$work/student/MyAlgorithm.py" --Vacuum.Autostart=true \
  --Vacuum.Referee.Duration=30 --rtf=4 --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
wait_for 30 "the first version to run" grep -q "python: drives at 0.00" "$work/run.log"
sim_pid=$(pgrep -f "aula-sim.*239.255.76.67:$port")
referee_pid=$(pgrep -f "vacuum-cleaner-referee.*239.255.76.67:$port")
version 0.3 broken
xdotool windowfocus --sync "$wid"
xdotool key --clearmodifiers ctrl+r
wait_for 30 "the syntax error's line" grep -q "the student's algorithm failed: MyAlgorithm.py:8: SyntaxError" "$work/run.log"
pgrep -f "vacuum-cleaner .*239.255.76.67:$port" >/dev/null || fail "the component went down on a syntax error"
version 0.3
xdotool windowfocus --sync "$wid"
xdotool key F5  # Run my algorithm: the fault stopped the run; Run takes the new version on disk first
wait_for 30 "the fixed version to run" grep -q "python: drives at 0.30" "$work/run.log"
wait_for 60 "the report of the last episode" grep -q '"reloads": 2' "$work/r.json"
[ "$(pgrep -f "aula-sim.*239.255.76.67:$port")" = "$sim_pid" ] || fail "the simulator was restarted"
[ "$(pgrep -f "vacuum-cleaner-referee.*239.255.76.67:$port")" = "$referee_pid" ] || fail "the referee was restarted"
kill -TERM $launcher
wait $launcher || true
sleep 0.5
if pgrep -af "239.255.76.67:$port"; then fail "processes left behind"; fi
[ "$(grep -c "with 1 robot(s)" "$work/run.log")" = 1 ] || fail "the simulator started more than once"
grep -q '"finished": true' "$work/r.json" || fail "the last episode was not graded to its end"
grep -q '"algorithm_error"' "$work/r.json" && fail "the last episode kept the syntax error's fault"
# Standing still cleans 0.16 % (the start footprint); 0.3 m/s for 30 s cleans well over 0.5 %.
coverage=$(sed -n 's/.*"coverage_percent": \([0-9.]*\).*/\1/p' "$work/r.json")
awk -v c="$coverage" 'BEGIN { exit !(c > 0.5) }' || fail "the last episode's coverage is $coverage %: the fixed version did not drive"
echo "python hot reload: a syntax error kept the component up; the fixed version ran in the same simulator; coverage $coverage %"
