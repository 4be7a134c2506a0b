#!/usr/bin/env bash
# Hot reload, the way a student does it, under a virtual display (Xvfb) driven with xdotool:
# windows open on a plugin built to stand still; the student rebuilds it to drive at 0.3 m/s
# and presses Ctrl+R in the component's window. The new build must run without restarting the
# simulator or the referee: the referee grades a new episode ("reloads": 1) in which the robot
# moved from its start, the simulator is the same process, and nothing is left behind.
# Usage: test_hot_reload.sh BUILD_DIR
set -euo pipefail
build="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-hot-reload-XXXXXX")"
port=$(python3 "$(dirname "$0")/../../free_udp_port.py")
cleanup() {
  pkill -TERM -f "239.255.76.67:$port" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  echo "--- the run printed:"; cat "$work/run.log" 2>/dev/null || true
  echo "--- the report:"; cat "$work/r.json" 2>/dev/null || true
  exit 1
}

"$build/bin/aula" new vacuum "$work/student" >/dev/null
cat >"$work/student/MyAlgorithm.cpp" <<'CPP'
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cstdio>

namespace aula::vacuum {
namespace {

constexpr double kSpeedMps = 0.0;  // rebuilt by the test with another speed

class MyAlgorithm : public VacuumAlgorithm {
 public:
  MyAlgorithm() { std::fprintf(stderr, "hot-reload plugin: built to drive at %.2f m/s\n", kSpeedMps); }
  void execute(VacuumApi& api) override {
    api.motors.sendV(kSpeedMps);
    api.motors.sendW(0.0);
  }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<MyAlgorithm>(); }

}  // namespace aula::vacuum
CPP
cmake -S "$work/student" -B "$work/student/build" >/dev/null
cmake --build "$work/student/build" >/dev/null
plugin="$work/student/build/libmy_algorithm.so"

export XDG_CACHE_HOME="$work/cache" XDG_RUNTIME_DIR="$work/runtime"
mkdir -m 700 -p "$XDG_RUNTIME_DIR"
# The steps inside the display; each wait is bounded, and says what it waited for.
cat >"$work/drive.sh" <<SH
set -euo pipefail
"$build/bin/aula" run vacuum --algorithm="$plugin" --Vacuum.Autostart=true --Vacuum.Referee.Duration=30 \
    --rtf=4 --report="$work/r.json" --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$work/run.log" 2>&1 &
launcher=\$!
wait_for() {  # wait_for SECONDS WHAT COMMAND...
  local deadline=\$((SECONDS + \$1)) what="\$2"; shift 2
  until "\$@" >/dev/null 2>&1; do
    [ \$SECONDS -lt \$deadline ] || { echo "timed out waiting for \$what"; return 1; }
    sleep 0.2
  done
}
wid=\$(timeout 30 xdotool search --sync --name '^Vacuum cleaner\$' | head -1)
[ -n "\$wid" ] || { echo "no component window"; exit 1; }
wait_for 120 "the first build to run" grep -q "built to drive at 0.00" "$work/run.log"
sim_pid=\$(pgrep -f "aula-sim.*239.255.76.67:$port")
referee_pid=\$(pgrep -f "vacuum-cleaner-referee.*239.255.76.67:$port")
sed -i 's/kSpeedMps = 0.0/kSpeedMps = 0.3/' "$work/student/MyAlgorithm.cpp"
cmake --build "$work/student/build" >/dev/null
xdotool windowfocus --sync "\$wid"
xdotool key --clearmodifiers ctrl+r
wait_for 120 "the new build to load" grep -q "loaded libmy_algorithm.so" "$work/run.log"
# Reloaded while its episode ran, the new build runs on at once; reloaded after the episode's end
# (a busy machine rebuilt it slower than the 30 s episode runs at 4x), it waits for Run: pressed
# then. Either way the new build runs in the same simulator, whatever the machine's speed.
wait_for 120 "the new build to run or to wait for Run" bash -c "grep -q 'built to drive at 0.30' '$work/run.log' || sed -n '/loaded libmy_algorithm.so/,\\\$p' '$work/run.log' | grep -q 'waiting for Run'"
if ! grep -q "built to drive at 0.30" "$work/run.log"; then
  xdotool windowfocus --sync "\$wid"
  xdotool key --clearmodifiers F5
fi
wait_for 120 "the new build to run" grep -q "built to drive at 0.30" "$work/run.log"
wait_for 120 "the report of the reloaded episode" grep -q '"reloads": 1' "$work/r.json"
[ "\$(pgrep -f "aula-sim.*239.255.76.67:$port")" = "\$sim_pid" ] || { echo "the simulator was restarted"; exit 1; }
[ "\$(pgrep -f "vacuum-cleaner-referee.*239.255.76.67:$port")" = "\$referee_pid" ] || { echo "the referee was restarted"; exit 1; }
kill -TERM \$launcher
wait \$launcher || true
SH
xvfb-run -a -s "-screen 0 1280x900x24" bash "$work/drive.sh" >"$work/drive.log" 2>&1 || fail "$(cat "$work/drive.log")"

sleep 0.5
if pgrep -f "239.255.76.67:$port" >/dev/null; then fail "processes left behind: $(pgrep -af "239.255.76.67:$port")"; fi
[ "$(grep -c "with 1 robot(s)" "$work/run.log")" = 1 ] || fail "the simulator started more than once"
grep -q "teleported" "$work/run.log" || fail "the robot was not put back at its start"
grep -q '"finished": true' "$work/r.json" || fail "the reloaded episode was not graded to its end"
# Standing still cleans 0.16 % (the start footprint); 0.3 m/s for 30 s cleans well over 0.5 %.
coverage=$(sed -n 's/.*"coverage_percent": \([0-9.]*\).*/\1/p' "$work/r.json")
awk -v c="$coverage" 'BEGIN { exit !(c > 0.5) }' || fail "the reloaded episode's coverage is $coverage %: the new build did not drive"
echo "hot reload: new build ran in the same simulator; reloaded episode's coverage $coverage %"
