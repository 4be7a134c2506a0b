#!/usr/bin/env bash
# The component window's speed control changes the simulator's pace: the sim seconds per wall
# second on SIM_CLOCK at 1x real time, then after Ctrl+] (5x), once Run has let the world go.
# Usage: test_speed_control.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start speed-control "$@"

"$build/bin/aula-test-lcm-probe" "$url" 100 >"$work/bus.log" &
"$build/bin/aula" run vacuum --algorithm=reference --lcm-url="$url" >"$work/run.log" 2>&1 &
launcher=$!
wid=$(find_window '^Vacuum cleaner$')
wait_for 30 "the simulator's clock" grep -q "^CLOCK" "$work/bus.log"

now_wall() { grep '^CLOCK' "$work/bus.log" | tail -n1 | awk '{ print $2 }'; }
# Sim seconds per wall second over the probe's wall-time window [from, to].
pace() { awk -v from="$1" -v to="$2" '/^CLOCK/ && $2 >= from && $2 <= to { if (!n++) { w0 = $2; s0 = $3 } w = $2; s = $3 }
                                      END { printf "%.2f\n", (n > 1 && w > w0) ? (s - s0) / (w - w0) : 0 }' "$work/bus.log"; }

xdotool windowfocus --sync "$wid"
xdotool key F5  # Run my algorithm: until then the world is held at 0 s
xdotool key ctrl+bracketright  # "as started" -> 1x real time
sleep 1
t0=$(now_wall)
sleep 4
t1=$(now_wall)
real_time=$(pace "$t0" "$t1")
xdotool key ctrl+bracketright  # 1x -> 5x
sleep 1
t2=$(now_wall)
sleep 4
t3=$(now_wall)
five_x=$(pace "$t2" "$t3")
kill -TERM $launcher
wait $launcher || true
awk -v p="$real_time" 'BEGIN { exit !(p > 0.8 && p < 1.2) }' || fail "at 1x the simulator ran $real_time sim s per wall s"
awk -v p="$five_x" 'BEGIN { exit !(p > 3.5 && p < 6) }' || fail "at 5x the simulator ran $five_x sim s per wall s"
echo "speed control: $real_time sim s per wall s at 1x, $five_x at 5x"
