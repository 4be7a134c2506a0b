#!/usr/bin/env bash
# Every window (the three components and the three referees), stopped with SIGTERM (the
# launcher at a run's end) or SIGINT (Ctrl-C), closes: the process leaves lockstep (the simulator
# says so; it is not dropped as silent) and exits 0, instead of dying of the signal.
# Usage: test_windows_stop_cleanly.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start windows_stop "$1"

"$build/bin/aula-sim" "$build/share/aula/worlds/vacuum.world" --lockstep --rtf=1 --lcm-url="$url" >"$work/sim.log" 2>&1 &
sim=$!
for program in vacuum-cleaner vacuum-cleaner-referee; do
  for signal in TERM INT; do
    "$build/bin/$program" --lcm-url="$url" >"$work/$program-$signal.log" 2>&1 &
    pid=$!
    wait_for 20 "$program joining lockstep" grep -q "'${program/-cleaner-referee/-referee}' joined" "$work/sim.log"
    sleep 0.5
    kill "-$signal" "$pid"
    code=0
    wait "$pid" || code=$?
    [ "$code" -eq 0 ] || fail "$program ended with $code on SIG$signal (expected 0)"
    wait_for 10 "$program leaving lockstep" grep -q "'${program/-cleaner-referee/-referee}' left" "$work/sim.log"
    # The next round joins again: forget this one's lines.
    : >"$work/sim.log"
  done
done
kill -TERM "$sim"
wait "$sim" || true
# The other exercises' windows, with no simulator (they wait for one): the same close.
for program in teletaxi teletaxi-referee autopark autopark-referee; do
  "$build/bin/$program" --lcm-url="$url" >"$work/$program.log" 2>&1 &
  pid=$!
  sleep 2
  kill -TERM "$pid"
  code=0
  wait "$pid" || code=$?
  [ "$code" -eq 0 ] || fail "$program ended with $code on SIGTERM (expected 0)"
done
echo "every window closes cleanly on SIGTERM and SIGINT"
