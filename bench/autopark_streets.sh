#!/usr/bin/env bash
# The Autopark references' park rate over generated streets and starts (issue 44): STREETS streets
# drawn from SEED by worlds/tools/make_autopark.py, each with five starts 2 m apart along the lane
# (facing +x, from anywhere on the street: before the slot, beside it or past it), each run headless
# in lockstep (simulator + component + referee) by each ALGORITHM. A street draws: the slot (1.3 to
# 2.25 car lengths), its neighbours (car, van, small), the curb offset (-1 to 1 m), free curb at
# the west end (the slot 3 to 25 m further east) and at the east end (none, or 2 to 10 m), the
# car's kinematics (turning in place or car-like). One Markdown row per algorithm: parked (the
# referee's "parked", no contact), declined with a reason (DECLINED or FAILED in the log), parked
# elsewhere, collided, any other end (no reason given: a silent stall). Each run not parked is
# listed on stderr with its world's parameters, start and last phase line.
#   bench/autopark_streets.sh [BUILD_DIR] [STREETS] [SEED] [ALGORITHMS]
#   e.g. bench/autopark_streets.sh build 10 1 "reactive planner"
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-build}" streets="${2:-10}" seed="${3:-1}" algorithms="${4:-reactive planner}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
port=$(python3 "$here/../tests/free_udp_port.py")

# One line per street: its generator flags, then the five start x (the lane at y 2.5).
python3 - "$here/../worlds/tools" "$streets" "$seed" >"$out/streets" <<'PY'
import random, sys
sys.path.insert(0, sys.argv[1])
import make_autopark as m
rng = random.Random(int(sys.argv[3]))
for _ in range(int(sys.argv[2])):
    slot = round(m.CAR_LENGTH_M * rng.uniform(1.3, 2.25), 2)
    rear, front = rng.choice(list(m.NEIGHBOURS)), rng.choice(list(m.NEIGHBOURS))
    slot_x = round(m.SLOT_START_X + rng.uniform(3, 25), 2)
    free = None if rng.random() < 0.3 else round(rng.uniform(2, 10), 2)
    curb = round(rng.uniform(-1, 1), 2)
    kin = rng.choice(["diff", "ackermann"])
    west, east = m.road_extent(m.parked_xs(slot, slot_x, rear, front), None, free)
    first = rng.uniform(west + 4, east - 4 - 8)  # five starts 2 m apart, all on the road
    flags = (f"--slot-length {slot} --slot-x {slot_x} --curb-offset {curb} --kinematics {kin}"
             f" --rear-neighbour {rear} --front-neighbour {front}" + ("" if free is None else f" --free-curb {free}"))
    print(flags + " | " + " ".join(f"{first + 2 * i:.2f}" for i in range(5)))
PY

echo "| algorithm | street/start pairs | parked | declined (a reason given) | parked elsewhere | collided | other (silent) |"
echo "|---|---|---|---|---|---|---|"
for algorithm in $algorithms; do
  parked=0 declined=0 elsewhere=0 collided=0 other=0 total=0 index=0
  while IFS='|' read -r flags starts; do
    index=$((index + 1))
    world="$out/street-$index.world"
    # shellcheck disable=SC2086  # the flags are words
    python3 "$here/../worlds/tools/make_autopark.py" --out "$world" $flags >/dev/null
    for x in $starts; do
      report="$out/r.json" log="$out/r.log"
      rm -f "$report"
      nice -n 10 "$build/bin/aula" run autopark --headless --algorithm="$algorithm" --seed=1 --world="$world" \
        "--Simulator.StartPose.car=$x,2.5,0" --report="$report" --lcm-url="udpm://239.255.76.67:$port?ttl=0" \
        >"$log" 2>&1 || true
      total=$((total + 1))
      if grep -q '"parked": true' "$report" && grep -q '"collisions": 0,' "$report"; then
        parked=$((parked + 1)); continue
      fi
      if ! grep -q '"collisions": 0,' "$report"; then collided=$((collided + 1)); kind=collided
      elif grep -q '"case": "parked_elsewhere"' "$report"; then elsewhere=$((elsewhere + 1)); kind=elsewhere
      elif grep -qE "^$algorithm .*(DECLINED|FAILED)" "$log"; then declined=$((declined + 1)); kind=declined
      else other=$((other + 1)); kind=other; fi
      echo "  $algorithm $kind: street $index ($flags) from x $x: $(grep -E "^$algorithm \[" "$log" | tail -1)" >&2
    done
  done <"$out/streets"
  echo "| $algorithm | $total | $parked | $declined | $elsewhere | $collided | $other |"
done
