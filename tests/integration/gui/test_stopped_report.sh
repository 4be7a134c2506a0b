#!/usr/bin/env bash
# With windows, a run stopped with Ctrl-C before its episode's end still leaves the report of that
# episode, graded so far and unfinished (before: none, or after a reload the last finished
# episode's). However far the run got when the signal came, its episode cannot have ended: 900 s
# of sim time at four times real time.
# Usage: test_stopped_report.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start stopped-report "$@"

"$build/bin/aula" run vacuum --algorithm=reference --Vacuum.Autostart=true --lockstep --rtf=4 \
  --report="$work/r.json" --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
find_window '^Vacuum cleaner referee' >/dev/null
kill -INT $launcher
code=0
wait $launcher || code=$?
[ "$code" -eq 130 ] || fail "the launcher stopped by SIGINT exits 130, not $code"
[ -s "$work/r.json" ] || fail "no report after Ctrl-C"
python3 - "$work/r.json" <<'PY' || fail "the report is not the stopped episode's: $(cat "$work/r.json")"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["finished"] is False and r["sim_time_s"] < 900, r
PY
grep -q "stopped before the end of the episode" "$work/run.log" || fail "the terminal does not say the episode was cut short"
echo "a run stopped with Ctrl-C leaves its unfinished episode's report"
