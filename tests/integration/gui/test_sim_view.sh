#!/usr/bin/env bash
# aula-sim --gui opens its 3D view (the module lib/aula/libaula_sim_view.so) and saves a frame
# with --screenshot, of the size Simulator.Window.Size says; a headless simulator never loads
# OpenSceneGraph.
# Usage: test_sim_view.sh BUILD_DIR
set -euo pipefail
source "$(dirname "$0")/lib.sh"
gui_test_start sim-view "$@"

world="$build/share/aula/worlds/vacuum.world"
"$build/bin/aula-sim" "$world" --duration 20 --rtf 1 --lcm-url="$url" >"$work/headless.log" 2>&1 &
headless=$!
wait_for 20 "the headless simulator to tick" grep -q "aula-sim: world" "$work/headless.log"
if grep -q "libosg" "/proc/$headless/maps"; then fail "a headless simulator has OpenSceneGraph loaded"; fi
kill -TERM $headless
wait $headless || true

port=$(python3 "$(dirname "$0")/../../free_udp_port.py")
timeout 60 "$build/bin/aula-sim" "$world" --gui --screenshot="$work/view.png" --duration 3 --rtf 1 \
  --Simulator.Window.Size="640, 360" \
  --lcm-url="udpm://239.255.76.67:$port?ttl=0" >"$work/gui.log" 2>&1 || fail "aula-sim --gui failed"
[ -s "$work/view.png" ] || fail "no screenshot of the 3D view"
python3 - "$work/view.png" <<'PY' || fail "the screenshot does not show the world"
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
width, height = struct.unpack('>II', data[16:24])
assert (width, height) == (640, 360), (width, height)
# The picture is not one colour: walls, floor and the robot (its orange) are drawn.
raw, at = b'', 8
while at < len(data):
    length, kind = struct.unpack('>I4s', data[at:at + 8])
    if kind == b'IDAT':
        raw += data[at + 8:at + 8 + length]
    at += 12 + length
pixels = zlib.decompress(raw)
assert len(set(pixels[i:i + 3] for i in range(1, min(len(pixels), 400000), 97))) > 3, 'a blank picture'
PY
echo "sim view: a headless simulator without OpenSceneGraph; --gui saved a 640x360 frame of the world"
