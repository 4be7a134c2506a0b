#!/usr/bin/env bash
# The vacuum's one episode clock, with windows, driven as a student does (xdotool keys):
# (a) before "Run my algorithm" the referee's clock stands still and teleoperating the robot
#     cleans nothing (the referee's status says elapsed 0 and coverage 0.00 % while the robot
#     drives); its clock starts at Run;
# (b) at the end the component's window says the referee's "Time's up" with the report's
#     coverage, and its own count since Run agrees with the referee's.
# The bus is read with aula-test-lcm-probe. Usage: test_episode_clock.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start episode-clock "$@"
duration_s=20

"$build/bin/aula-test-lcm-probe" "$url" 200 >"$work/bus.log" &
"$build/bin/aula" run vacuum --algorithm=reference --Vacuum.Referee.Duration=$duration_s --rtf=4 \
  --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
find_window '^Vacuum cleaner referee$' >/dev/null
wait_for 30 "the referee's first status" grep -q "^STATUS VACUUM_REFEREE" "$work/bus.log"

# How far the robot is from its first pose, in metres.
moved_m() { awk '/^POSE ROOMBA_POSE/ { if (!n++) { x0 = $5; y0 = $6 } x = $5; y = $6 }
                 END { printf "%.3f\n", n ? sqrt((x - x0)^2 + (y - y0)^2) : 0 }' "$work/bus.log"; }
moved_at_least() { awk -v d="$(moved_m)" -v want="$1" 'BEGIN { exit !(d >= want) }'; }

# Teleoperate before Run: W twice is half the top speed forward; X stops.
xdotool windowfocus --sync "$wid"
xdotool key w w
wait_for 30 "the teleoperator to drive the robot 0.5 m" moved_at_least 0.5
xdotool key x
sleep 1
before_run_m=$(moved_m)
xdotool key F5  # Run my algorithm
wait_for 90 "the referee's report at the end of the episode" grep -q '"finished": true' "$work/r.json"
wait_for 10 "the component's own count at the end" grep -q "this window counted" "$work/run.log"
kill -TERM $launcher
wait $launcher || true

# (a) Every status before Run: the clock at 0 and nothing cleaned, over seconds of teleoperation.
awk '/^STATUS VACUUM_REFEREE/ && /started=0/' "$work/bus.log" >"$work/before_run.txt"
[ "$(wc -l <"$work/before_run.txt")" -ge 3 ] || fail "fewer than 3 statuses before Run"
grep -vE "elapsed=0.000 .*summary=coverage 0.00 %( - not its seed's graded run: teleoperated before Run)?$" "$work/before_run.txt" \
  && fail "the referee's clock or coverage moved before Run"
# Teleoperated before Run, the run is not its seed's graded run: every window's status says so
# (the referee's), and so does the report.
grep -q "^STATUS VACUUM_REFEREE.*summary=coverage .* - not its seed's graded run: teleoperated before Run$" "$work/bus.log" \
  || fail "the referee's status never said the run is not its seed's graded run"
grep -q '"not_the_seeds_run": "teleoperated before Run"' "$work/r.json" || fail "the report does not say the run is not its seed's graded run"
grep -q "teleoperated before Run: this run is no longer the graded run of its seed" "$work/run.log" || fail "the component did not say it"
first_started=$(grep -m1 "^STATUS VACUUM_REFEREE.*started=1" "$work/bus.log") || fail "the referee never started the episode"
last_waiting_sim=$(tail -n1 "$work/before_run.txt" | sed -n 's/.* sim=\([0-9.]*\) .*/\1/p')
started_sim=$(echo "$first_started" | sed -n 's/.* sim=\([0-9.]*\) .*/\1/p')
started_elapsed=$(echo "$first_started" | sed -n 's/.* elapsed=\([0-9.]*\) .*/\1/p')
# The referee hears of Run on the episode channel, a datagram of its own: a status it sends at its
# next period (1 s) may come before it (CI, under load: Run at 7.84 s, "waiting" said at 8.00 s).
# The episode still counts from Run; teleoperation before it lasts seconds.
awk -v s="$started_sim" -v e="$started_elapsed" -v w="$last_waiting_sim" 'BEGIN { exit !(s - e >= w - 1.0) }' \
  || fail "the episode's clock started at $started_sim - $started_elapsed s, before the last status that waited for Run ($last_waiting_sim s)"
grep -q "^STATUS VACUUM_REFEREE.*finished=1 ending=Time's up; summary=coverage" "$work/bus.log" \
  || fail "no final status saying Time's up"
grep -q "elapsed=$duration_s.000 .*finished=1" "$work/bus.log" || fail "the episode did not last $duration_s s of sim time"

# (b) The window said the referee's end with the report's coverage, and counted the same.
report=$(sed -n 's/.*"coverage_percent": \([0-9.]*\).*/\1/p' "$work/r.json")
said=$(sed -n "s/.*the referee ended the episode at .*: Time's up: coverage \([0-9.]*\) %.*/\1/p" "$work/run.log")
counted=$(sed -n 's/.*this window counted \([0-9.]*\) %.*/\1/p' "$work/run.log")
[ -n "$said" ] || fail "the component did not say Time's up"
awk -v a="$said" -v b="$report" 'BEGIN { exit !(a - b < 0.006 && b - a < 0.006) }' \
  || fail "the window said coverage $said %, the report has $report %"
awk -v a="$counted" -v b="$report" 'BEGIN { exit !(a - b < 0.5 && b - a < 0.5) }' \
  || fail "the window counted $counted %, the referee $report %"
awk -v c="$report" 'BEGIN { exit !(c > 0.5) }' || fail "the reference cleaned only $report % in $duration_s s"
echo "episode clock: still for $(wc -l <"$work/before_run.txt") statuses while teleoperated $before_run_m m;" \
  "at the end the referee graded $report %, the window counted $counted %"
