#!/usr/bin/env bash
# A crash inside the student's execute() with windows (the segfault plugin) does not end the
# run: the component's window stays, its fault panel and the terminal name the student's line
# (read from the plugin's source, not a constant), the robot stops, and the referee is told as
# of an exception ("algorithm_error" in its report). The referee's window then shows the sim
# time the run stopped at and the report's mark as final (not the clock running on and a mark
# "so far"). The student fixes the build (the bounce plugin copied over it) and presses Ctrl+R:
# the new build runs in the same processes, the referee's window clears the last mark, and the
# new episode is graded to its end from zero.
# Usage: test_crash_with_windows.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start crash-with-windows "$@"
plugins="$build/tests/integration/plugins"
[ -f "$plugins/libaula_test_fault_segfault.so" ] || fail "no segfault plugin in $plugins"
mkdir "$work/student"
cp "$plugins/libaula_test_fault_segfault.so" "$work/student/libmy_algorithm.so"
line=$(grep -n '\*nowhere = calls_;' "$(dirname "$0")/../../data/plugins/segfault.cpp" | cut -d: -f1)
where="segfault.cpp:$line (Segfault::execute)"

"$build/bin/aula" run vacuum --algorithm="$work/student/libmy_algorithm.so" --Vacuum.Autostart=true \
  --Vacuum.Referee.Duration=20 --rtf=4 --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
find_window '^Vacuum cleaner referee$' >/dev/null
wait_for 30 "the crash's line in the fault" grep -q "the student's algorithm failed: execute() crashed (SIGSEGV) at $where" "$work/run.log"
grep -q "vacuum-cleaner: crashed (SIGSEGV) in your algorithm at $where" "$work/run.log" || fail "the terminal does not name the line"
wait_for 10 "the referee's report" grep -q "\"algorithm_error\": \"execute() crashed (SIGSEGV) at $where\"" "$work/r.json"
grep -q '"finished": false' "$work/r.json" || fail "the report does not say the run ended early"
grep -q '"aborted"' "$work/r.json" && fail "the run was aborted: the component died"
component=$(pgrep -f "vacuum-cleaner .*239.255.76.67:$port") || fail "the component ended"
xdotool search --name '^Vacuum cleaner$' >/dev/null || fail "the component's window closed"

# The referee's window: the stop time and the final mark, the report's, said once it ended.
stopped=$(sed -n 's/.*"sim_time_s": \([0-9.]*\).*/\1/p' "$work/r.json")
mark=$(sed -n 's/.*"mark": \([0-9.]*\).*/\1/p' "$work/r.json")
wait_for 10 "the referee's window to show the end" grep -q "^Vacuum cleaner referee shows: Stopped at" "$work/run.log"
shown=$(grep -m1 "^Vacuum cleaner referee shows: Stopped at" "$work/run.log")
shown_s=$(echo "$shown" | sed -n 's/.*Stopped at \([0-9.]*\) s of sim time.*/\1/p')
shown_mark=$(echo "$shown" | sed -n 's/.*| Mark: \([0-9.]*\) \/ 10 .*/\1/p')
awk -v a="$shown_s" -v b="$stopped" 'BEGIN { exit !(a - b < 0.006 && b - a < 0.006) }' \
  || fail "the referee's window says it stopped at '$shown_s' s, the report at $stopped s: $shown"
awk -v a="$shown_mark" -v b="$mark" 'BEGIN { exit !(a - b < 0.006 && b - a < 0.006) }' \
  || fail "the referee's window says mark '$shown_mark', the report $mark: $shown"
echo "$shown" | grep -q "so far" && fail "the referee's window calls the final mark 'so far': $shown"

# Fixed and rebuilt: Ctrl+R loads the new build in the same processes, Run runs a fresh episode.
cp "$plugins/libaula_test_vacuum_bounce.so" "$work/student/libmy_algorithm.so.new"
mv "$work/student/libmy_algorithm.so.new" "$work/student/libmy_algorithm.so"  # as a linker replaces it
xdotool windowfocus --sync "$wid"
xdotool key --clearmodifiers ctrl+r
wait_for 30 "the new build to load" grep -q "vacuum-cleaner: loaded libmy_algorithm.so" "$work/run.log"
wait_for 30 "the referee's window to clear the last mark" grep -q "^Vacuum cleaner referee shows: .* | Mark: -$" "$work/run.log"
xdotool windowfocus --sync "$wid"
xdotool key F5  # Run my algorithm: the crash stopped it
wait_for 60 "the report of the new episode" grep -q '"reloads": 1' "$work/r.json"
grep -q '"finished": true' "$work/r.json" || fail "the new episode was not graded to its end"
grep -q '"algorithm_error"' "$work/r.json" && fail "the new episode kept the crash's fault"
[ "$(pgrep -f "vacuum-cleaner .*239.255.76.67:$port")" = "$component" ] || fail "the component was restarted"
new_mark=$(sed -n 's/.*"mark": \([0-9.]*\).*/\1/p' "$work/r.json")
wait_for 10 "the referee's window to show the new end" grep -q "^Vacuum cleaner referee shows: Time's up at 20.00 s" "$work/run.log"
new_shown=$(grep -m1 "^Vacuum cleaner referee shows: Time's up" "$work/run.log" | sed -n 's/.*| Mark: \([0-9.]*\) \/ 10 .*/\1/p')
awk -v a="$new_shown" -v b="$new_mark" 'BEGIN { exit !(a - b < 0.006 && b - a < 0.006) }' \
  || fail "the referee's window shows mark '$new_shown' for the new episode, the report $new_mark"
kill -TERM $launcher
wait $launcher || true
sleep 0.5
if pgrep -af "239.255.76.67:$port" | grep -v "pgrep"; then fail "processes left behind"; fi
echo "a crash with windows named $where in the fault panel; the referee's window stopped at $shown_s s with" \
  "mark $shown_mark; after Ctrl+R the new build's episode was graded from zero to $new_mark"
