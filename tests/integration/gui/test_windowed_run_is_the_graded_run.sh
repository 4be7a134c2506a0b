#!/usr/bin/env bash
# What the student watches is what is graded (issue 58): a windowed run of the vacuum's reference,
# started with F5 ("Run my algorithm") at 10x real time beside four busy loops, ends with the very
# report of the headless run of the same seed and duration: with windows the run is in lockstep by
# default and the world is held at 0 s until Run. Usage: test_windowed_run_is_the_graded_run.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start windowed-is-graded "$@"
duration_s=120

for _ in 1 2 3 4; do timeout 900 sh -c 'while :; do :; done' & done
busy=$(jobs -p)
trap 'kill $busy 2>/dev/null || true; gui_test_cleanup' EXIT

"$build/bin/aula" run vacuum --algorithm=reference --rtf=10 --duration=$duration_s --seed=1 \
  --report="$work/windowed.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
find_window '^Vacuum cleaner referee$' >/dev/null
sleep 2  # whenever Run is pressed, the world is where it was at 0 s
xdotool windowfocus --sync "$wid"
xdotool key F5  # Run my algorithm
wait_for 600 "the windowed run's report" grep -q '"finished": true' "$work/windowed.json"
kill -TERM $launcher
wait $launcher || true

port2=$(python3 "$(dirname "$0")/../../free_udp_port.py")
"$build/bin/aula" run vacuum --headless --algorithm=reference --duration=$duration_s --seed=1 \
  --report="$work/headless.json" --lcm-url="udpm://239.255.76.67:$port2?ttl=0" >"$work/headless.log" 2>&1 \
  || fail "the headless run failed"
kill $busy 2>/dev/null || true

for field in coverage_percent bumps stuck_s mark; do
  w=$(sed -n "s/.*\"$field\": \([0-9.e+-]*\).*/\1/p" "$work/windowed.json" | head -1)
  h=$(sed -n "s/.*\"$field\": \([0-9.e+-]*\).*/\1/p" "$work/headless.json" | head -1)
  [ -n "$h" ] || fail "no $field in the headless report"
  [ "$w" = "$h" ] || fail "$field: windowed $w, headless $h"
done
cmp -s "$work/windowed.json" "$work/headless.json" || fail "the reports differ: $(diff "$work/windowed.json" "$work/headless.json" | head -20)"
echo "PASS: the windowed run's report is the headless run's, byte for byte"
