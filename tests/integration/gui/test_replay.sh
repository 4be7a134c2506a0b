#!/usr/bin/env bash
# aula replay under Xvfb: a recorded vacuum run played back into the component and referee
# windows at 100x. The referee window grades the replayed stream, and its report must equal the
# live run's byte for byte (nothing lost on the way), and the component window counts the same
# cleaning; a screenshot of the three windows is taken at the end. Then what is not a recorded run is refused with exit 2.
# Usage: test_replay.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-replay-XXXXXX")"
port=$(python3 "$(dirname "$0")/../../free_udp_port.py")
trap 'pkill -TERM -f "$work" 2>/dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; cat "$work"/*.txt 2>/dev/null || true; exit 1; }

export XDG_CACHE_HOME="$work/cache" XDG_RUNTIME_DIR="$work/runtime"
mkdir -m 700 -p "$XDG_RUNTIME_DIR"
"$build/bin/aula" run vacuum --headless --algorithm=reference --seed=2 --Vacuum.Referee.Duration=60 \
  --record="$work/run.lcmlog" --report="$work/live.json" --lcm-url="udpm://239.255.76.67:$port?ttl=0" \
  >"$work/live.txt" 2>&1 || fail "the recorded run failed"

xvfb-run -a -s "-screen 0 1600x1000x24" "$build/bin/aula" replay "$work/run.lcmlog" --speed=100 \
  --report="$work/replayed.json" --screenshot="$work/replay.png" --screenshot-at=1000 >"$work/replay.txt" 2>&1 \
  || fail "aula replay failed"
[ -s "$work/replay.png" ] || fail "no screenshot"
[ -s "$work/replayed.json" ] || fail "the referee window wrote no report"
cmp "$work/live.json" "$work/replayed.json" || { diff "$work/live.json" "$work/replayed.json"; fail "the replayed grade differs from the live one"; }
if pgrep -f "$work/run.lcmlog" >/dev/null; then fail "processes left behind"; fi
# The view-only component window counts the replayed cleaning too (the recorded episode's start,
# from the referee's word), as the live window would have.
report=$(sed -n 's/.*"coverage_percent": \([0-9.]*\).*/\1/p' "$work/live.json")
counted=$(sed -n 's/.*this window counted \([0-9.]*\) %.*/\1/p' "$work/replay.txt")
[ -n "$counted" ] || fail "the component window did not say what it counted"
awk -v a="$counted" -v b="$report" 'BEGIN { exit !(a - b < 0.5 && b - a < 0.5 && b > 0.5) }' \
  || fail "the replayed component window counted $counted %, the referee $report %"

printf 'not a log\n' >"$work/text.lcmlog"
set +e
DISPLAY= "$build/bin/aula" replay "$work/text.lcmlog" >"$work/refused.txt" 2>&1
code=$?
set -e
[ "$code" = 2 ] || fail "a text file: exit $code, expected 2"
grep -q "not an LCM log" "$work/refused.txt" || fail "no reason given: $(cat "$work/refused.txt")"
echo "replay: the replayed referee's report equals the live run's; the component window counted $counted % ($report %)"
