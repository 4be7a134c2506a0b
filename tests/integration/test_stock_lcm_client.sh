#!/usr/bin/env bash
# A stock LCM client (python-lcm, an independent process) on the run's URL decodes every channel
# of a running exercise with the project's own types (lcm-gen -p), although each channel travels
# on a multicast group of its own (docs/architecture.md, "The bus"). It must see every pose the
# referee graded.
# Usage: test_stock_lcm_client.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir="$1"
build="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-stock-client-XXXXXX")"
port=$(python3 "$(dirname "$0")/../free_udp_port.py")
url="udpm://239.255.76.67:$port?ttl=0&recv_buf_size=4194304"
listener=""
trap '[ -n "$listener" ] && kill "$listener" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; cat "$work"/*.txt 2>/dev/null || true; exit 1; }

python3 -c 'import lcm' || fail "python-lcm is missing (scripts/install-deps.sh installs it)"
mkdir "$work/types"
lcm-gen -p --ppath "$work/types" "$source_dir"/lcmtypes/*.lcm >/dev/null

python3 "$source_dir/tests/integration/stock_lcm_client.py" "$url" "$work/types" "$work/ready" "$work/stop" \
  >"$work/seen.txt" 2>"$work/client.txt" &
listener=$!
while [ ! -e "$work/ready" ] && kill -0 "$listener" 2>/dev/null; do sleep 0.1; done  # however slow its start
[ -e "$work/ready" ] || fail "python-lcm did not start"

# Paced at real time: lockstep waits for its clients, never for an observer, and a Python
# decoder starved of CPU by other tests falls behind a faster run until the kernel's queue
# overflows (a third of the poses lost at 700x, 11 of 1501 at 10x and 16 at 5x at load 10, with
# the reference's belief maps). At 1x the decoder needs a fifth of a core.
"$build/bin/aula" run vacuum --headless --rtf=1 --algorithm=reference --seed=3 --Vacuum.Referee.Duration=30 \
  --report="$work/report.json" --lcm-url="$url" >"$work/run.txt" 2>&1 || fail "the run failed"
# The run is over: the client reads what is queued up to the poses the referee graded, then ends
# (it never guesses the run's end from a silence, which a loaded machine can make at any time).
graded=$(grep '"pose_messages"' "$work/report.json" | sed 's/[^0-9]//g')
[ -n "$graded" ] || fail "the report has no pose_messages"
echo "$graded" >"$work/stop.tmp" && mv "$work/stop.tmp" "$work/stop"
wait "$listener" || fail "python-lcm could not decode every message"
listener=""

for expected in "SIM_CLOCK sim_clock_t" "SIM_LOCKSTEP_REGISTER lockstep_register_t" "SIM_LOCKSTEP_ACK lockstep_ack_t" \
                "ROOMBA_POSE pose3d_t" "ROOMBA_LASER laser_t" "ROOMBA_BUMPER bumper_t" "ROOMBA_MOTORS motors_t" \
                "VACUUM_EPISODE episode_t" "VACUUM_BELIEF belief_t"; do
  grep -q "^$expected [0-9]" "$work/seen.txt" || fail "python-lcm never saw $expected"
done
seen=$(awk '$1 == "ROOMBA_POSE" {print $3}' "$work/seen.txt")
[ "$seen" -ge "$graded" ] || fail "python-lcm saw $seen poses, the referee graded $graded"
echo "python-lcm decoded every channel:"; cat "$work/seen.txt"
