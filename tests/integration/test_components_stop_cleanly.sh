#!/usr/bin/env bash
# A headless component stopped with SIGTERM (what the launcher sends at a run's end) leaves
# lockstep and exits 0, whatever threads its libraries started (TBB's workers under OpenCV in
# TeleTaxi once killed it with the signal's default action: exit 143).
# Usage: test_components_stop_cleanly.sh BUILD_DIR
set -euo pipefail
build="$1"
port=$(python3 "$(dirname "$0")/../free_udp_port.py")
for program in teletaxi vacuum-cleaner autopark; do
  "$build/bin/$program" --headless --lcm-url="udpm://239.255.76.67:$port?ttl=0" >/dev/null 2>&1 &
  pid=$!
  sleep 1.5
  kill -TERM "$pid"
  code=0
  wait "$pid" || code=$?
  [ "$code" -eq 0 ] || { echo "FAIL: $program ended with $code on SIGTERM (expected 0)"; exit 1; }
done
echo "every component stops cleanly on SIGTERM"
