#!/usr/bin/env bash
# The TeleTaxi city as boxes (worlds/cityLarge.world) beside the same city as one COLLADA mesh in
# RoboticsAcademy's form (Blender's [-1, 1] geometry under a node matrix scaling x and y by 250, a
# ground quad, every box and cylinder as triangles): how long loading takes (aula check-world, cold
# and warm parsed-world cache) and a reference TeleTaxi run on each (wall time, mark).
# Usage: bench/mesh_city.sh [BUILD_DIR] (default build). Figures go to docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
out="$(mktemp -d /tmp/aula-mesh-city-XXXXXX)"
trap 'rm -rf "$out"' EXIT
cp worlds/cityLarge.world "$out/boxes.world"
python3 - "$out" <<'PY'
import math, re, sys
out = sys.argv[1]
text = open("worlds/cityLarge.world").read()
solids = []  # (corners of the footprint polygon, height bottom, top)
pattern = re.compile(r'<collision name="[^"]*"><pose>([^<]*)</pose><geometry>(?:<box><size>([^<]*)</size></box>|'
                     r'<cylinder><radius>([^<]*)</radius><length>([^<]*)</length></cylinder>)')
for m in pattern.finditer(text):
    x, y, z, _, _, yaw = map(float, m.group(1).split())
    if m.group(2):
        sx, sy, sz = map(float, m.group(2).split())
        c, s = math.cos(yaw), math.sin(yaw)
        ring = [(x + c * a - s * b, y + s * a + c * b) for a, b in ((-sx/2, -sy/2), (sx/2, -sy/2), (sx/2, sy/2), (-sx/2, sy/2))]
    else:
        r, sz = float(m.group(3)), float(m.group(4))
        ring = [(x + r * math.cos(2 * math.pi * k / 24), y + r * math.sin(2 * math.pi * k / 24)) for k in range(24)]
    solids.append((ring, z - sz / 2, z + sz / 2))
tris = []
for ring, lo, hi in solids:  # a prism: sides, bottom fan, top fan (outward)
    n = len(ring)
    for k in range(n):
        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % n]
        tris += [(ax, ay, lo), (bx, by, lo), (bx, by, hi), (ax, ay, lo), (bx, by, hi), (ax, ay, hi)]
    for k in range(1, n - 1):
        tris += [(ring[0][0], ring[0][1], lo), (ring[k + 1][0], ring[k + 1][1], lo), (ring[k][0], ring[k][1], lo)]
        tris += [(ring[0][0], ring[0][1], hi), (ring[k][0], ring[k][1], hi), (ring[k + 1][0], ring[k + 1][1], hi)]
g = 250.0
tris += [(-g, -g, 0), (g, -g, 0), (g, g, 0), (-g, -g, 0), (g, g, 0), (-g, g, 0)]
floats = " ".join("%.6f %.6f %.6f" % (px / 250.0, py / 250.0, pz) for px, py, pz in tris)
dae = f'''<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="city-mesh" name="city"><mesh>
    <source id="city-pos"><float_array id="city-pos-array" count="{3 * len(tris)}">{floats}</float_array>
      <technique_common><accessor source="#city-pos-array" count="{len(tris)}" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
    <vertices id="city-vtx"><input semantic="POSITION" source="#city-pos"/></vertices>
    <triangles count="{len(tris) // 3}"><input semantic="VERTEX" source="#city-vtx" offset="0"/><p>{" ".join(map(str, range(len(tris))))}</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="Scene" name="Scene"><node id="City" name="City" type="NODE">
    <matrix sid="transform">250 0 0 0 0 250 0 0 0 0 1 0 0 0 0 1</matrix><instance_geometry url="#city-mesh"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
'''
open(f"{out}/city.dae", "w").write(dae)
model = ('<model name="city"><static>true</static><link name="buildings"><collision name="mesh"><geometry><mesh>'
         f'<uri>{out}/city.dae</uri></mesh></geometry></collision></link></model>')
world = re.sub(r'<model name="city">.*?</model>', model, text, count=1, flags=re.S)
open(f"{out}/mesh.world", "w").write(world)
print(f"mesh city: {len(solids)} solids, {len(tris) // 3} triangles, {len(dae) // 1024} KiB of COLLADA")
PY
export AULA_MODEL_PATH="$PWD/worlds/models"
# The median of three wall times of a command (seconds).
median3() {
  for i in 1 2 3; do /usr/bin/time -f %e -o "$out/t" "$@" >/dev/null 2>&1 || true; cat "$out/t"; done | sort -n | sed -n 2p
}
for kind in boxes mesh; do
  world="$out/$kind.world"
  export XDG_CACHE_HOME="$out/cache-$kind"
  cold=$(/usr/bin/time -f %e -o "$out/t" "$build/bin/aula" check-world "$world" --exercise=teletaxi >/dev/null 2>&1; cat "$out/t")
  warm=$(median3 "$build/bin/aula" check-world "$world" --exercise=teletaxi)
  run=$(median3 "$build/bin/aula" run teletaxi --headless --algorithm=reference --world="$world" \
          --TeleTaxi.Destination=120,-40 --report="$out/$kind.json")
  mark=$(python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(r['mark'], r['sim_time_s'])" "$out/$kind.json")
  echo "$kind: check-world (load and map) cold ${cold} s, warm ${warm} s; reference run to (120, -40): ${run} s wall (median of 3), mark and sim s: ${mark}"
done
