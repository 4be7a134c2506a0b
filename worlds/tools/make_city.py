#!/usr/bin/env python3
"""Writes worlds/cityLarge.world: a 500 x 500 m city centred on the origin.

A grid of roads (12-16 m wide) between blocks of buildings (each block split into four
touching buildings of different heights), a perimeter road inside the city wall, a
106 m square plaza with a fountain, a round tower with a curved road around it, an L-shaped sharp bend, and
in the north-west a 14 m wide quarter-circle boulevard whose building edges are chains of
rotated boxes (backed by axis-aligned "staircase" buildings, so no closed pocket of free space
is left behind them).
Deterministic: rerun after editing and commit the result (the world is data a teacher reads).
"""
import math
import random
import sys

random.seed(2018)

# Road centre lines and widths, the same along x and y.
ROADS = [(-240, 14), (-175, 14), (-120, 12), (0, 16), (120, 12), (175, 14), (240, 14)]
WALL = 250.0

boxes = []  # (name, cx, cy, sx, sy, height, yaw)
cylinders = []  # (name, cx, cy, radius, height)


def block_span(i):
    """Free interval between road i and road i+1."""
    (c0, w0), (c1, w1) = ROADS[i], ROADS[i + 1]
    return c0 + w0 / 2.0, c1 - w1 / 2.0


def buildings(name, x0, x1, y0, y1):
    """Four touching buildings filling the rectangle, of random heights."""
    xm, ym = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    for k, (a0, a1, b0, b1) in enumerate([(x0, xm, y0, ym), (xm, x1, y0, ym), (x0, xm, ym, y1), (xm, x1, ym, y1)]):
        h = random.choice([6, 9, 12, 15, 20, 25, 32, 40])
        boxes.append((f"{name}_{k}", (a0 + a1) / 2, (b0 + b1) / 2, a1 - a0, b1 - b0, h, 0.0))


n = len(ROADS) - 1
for i in range(n):
    for j in range(n):
        x0, x1 = block_span(i)
        y0, y1 = block_span(j)
        name = f"block_{i}_{j}"
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        # The plaza: the block north-west of the origin stays open, with a fountain.
        if (i, j) == (2, 3):
            cylinders.append(("plaza_fountain", cx, cy, 6.0, 3.0))
            continue
        # The round tower group (south-east, blocks 4..5 x 1..2 merged): a tower with a
        # curved road around it and four corner buildings.
        if i in (4, 5) and j in (1, 2):
            continue
        # The curved boulevard (north-west, blocks 0..1 x 4..5 merged): see below.
        if i in (0, 1) and j in (4, 5):
            continue
        buildings(name, x0, x1, y0, y1)

# Round tower in the south-east group (x 91..233, y -233..-91 incl. the roads inside).
gx0, gx1 = block_span(4)[0], block_span(5)[1]
gy0, gy1 = block_span(1)[0], block_span(2)[1]
gcx, gcy = (gx0 + gx1) / 2, (gy0 + gy1) / 2
cylinders.append(("round_tower", gcx, gcy, 28.0, 60.0))
side = 25.0
for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
    cx = gcx + sx * ((gx1 - gx0) / 2 - side / 2)
    cy = gcy + sy * ((gy1 - gy0) / 2 - side / 2)
    boxes.append((f"tower_corner_{k}", cx, cy, side, side, 18.0, 0.0))

# Curved boulevard in the north-west group (x -233..-91, y 91..233): a quarter circle centred
# near the group's south-east corner C, joining the road y = 85 (at x ~ -173) to the road
# x = -85 (at y ~ 173). Local frame: u = west of C, v = north of C.
def curved_group():
    gx0, gx1 = block_span(0)[0], block_span(1)[1]
    gy0, gy1 = block_span(4)[0], block_span(5)[1]
    L = gx1 - gx0                      # the group is square
    cx, cy = gx1, gy0                  # corner C
    sxw, syw = -1.0, 1.0               # local (u, v) -> world (cx + sxw*u, cy + syw*v)
    R, W, N = 80.0, 14.0, 10           # centre-line radius, road width, segments per quarter
    ri, ro = R - W / 2, R + W / 2
    dl = (math.pi / 2) / N
    h = ri * math.cos(dl / 2)          # distance of the inner chords from the arc centre
    d_in = 0.4 * h                     # radial depth of the inner chain
    m = d_in * math.sin(dl / 2)        # arc centre inset so no box pokes out of the group
    a0 = m                             # arc centre C' = (m, m) in local coordinates

    def box(name, u, v, su, sv, height, phi):
        # A box centred at local (u, v) with its x axis at local angle phi.
        yaw = math.atan2(syw * math.sin(phi), sxw * math.cos(phi))
        boxes.append((name, cx + sxw * u, cy + syw * v, su, sv, height, yaw))

    # Inner side: a chain of rotated boxes whose outer faces are the chords of the inner edge,
    # and an axis-aligned core behind them.
    for k in range(N):
        phi = (k + 0.5) * dl
        r = h - d_in / 2
        box(f"curve_inner_{k}", a0 + r * math.cos(phi), a0 + r * math.sin(phi), d_in,
            2 * ri * math.sin(dl / 2) + 0.05, 20.0, phi)
    a = m + (h - d_in) / math.cos(dl / 2) + 1.0
    assert (a - m) * math.sqrt(2) < h - 1.0
    box("curve_core", a / 2, a / 2, a, a, 30.0, 0.0)
    # Outer side: boxes tangent to the outer edge, boxes filling the V gaps at the joints.
    d_out = 15.0
    half = ro * math.tan(dl / 2)
    for k in range(N):
        phi = (k + 0.5) * dl
        r = ro + d_out / 2
        box(f"curve_outer_{k}", a0 + r * math.cos(phi), a0 + r * math.sin(phi), d_out,
            2 * half + 0.05, 12.0, phi)
    rv = ro / math.cos(dl / 2)
    for k in range(1, N):
        phi = k * dl
        r0, r1 = rv, ro + d_out
        r = (r0 + r1) / 2
        box(f"curve_joint_{k}", a0 + r * math.cos(phi), a0 + r * math.sin(phi), r1 - r0,
            2 * (d_out * math.tan(dl / 2) + 0.5), 12.0, phi)
    # Staircase of axis-aligned buildings beyond the chain band (they dip into the band, never
    # into the road): strips along u, each from the band's outer edge to the group's edge.
    rs = ro + d_out - 1.0
    step = 6.0
    u = 0.0
    while u < L - 1e-9:
        ub = min(L, u + step)
        if ub - a0 >= rs:
            ub = L  # past the arc: one building to the group's west edge
            vlow = 0.0
        else:
            vlow = a0 + math.sqrt(rs * rs - (ub - a0) ** 2)
        if vlow < L:
            dip = math.hypot(u - a0, vlow - a0) if vlow > 0 else abs(u - a0)
            assert dip > ro + 1.0, (u, vlow, dip)
            box(f"curve_stair_{len(boxes)}", (u + ub) / 2, (vlow + L) / 2, ub - u, L - vlow,
                random.choice([9, 12, 15, 20, 25]), 0.0)
        u = ub


curved_group()

# A sharp bend: close the road x = 175 between the two north-east blocks (y 91..169), so
# traffic from the north turns 90 degrees at y = 175.
(c, w) = ROADS[5]
y0, y1 = block_span(4)
boxes.append(("bend_closure", c, (y0 + y1) / 2, w, y1 - y0, 14.0, 0.0))

# City wall.
t = 2.0
boxes.append(("wall_north", 0, WALL - t / 2, 2 * WALL, t, 4.0, 0.0))
boxes.append(("wall_south", 0, -WALL + t / 2, 2 * WALL, t, 4.0, 0.0))
boxes.append(("wall_east", WALL - t / 2, 0, t, 2 * WALL - 2 * t, 4.0, 0.0))
boxes.append(("wall_west", -WALL + t / 2, 0, t, 2 * WALL - 2 * t, 4.0, 0.0))

out = []
out.append('<?xml version="1.0"?>')
out.append("<!-- cityLarge: a 500 x 500 m city centred on the origin, for the TeleTaxi exercise.")
out.append("     Generated by worlds/tools/make_city.py (edit the script, not this file). -->")
out.append('<sdf version="1.9">')
out.append('  <world name="cityLarge">')
out.append("    <physics type=\"dart\"><max_step_size>0.005</max_step_size></physics>")
out.append('    <model name="city">')
out.append("      <static>true</static>")
out.append('      <link name="buildings">')
for name, cx, cy, sx, sy, h, yaw in boxes:
    geom = f"<box><size>{sx:.3f} {sy:.3f} {h:.3f}</size></box>"
    pose = f"{cx:.3f} {cy:.3f} {h / 2:.3f} 0 0 {yaw:.6f}"
    out.append(f'        <collision name="{name}"><pose>{pose}</pose><geometry>{geom}</geometry></collision>')
    out.append(f'        <visual name="{name}"><pose>{pose}</pose><geometry>{geom}</geometry></visual>')
for name, cx, cy, r, h in cylinders:
    geom = f"<cylinder><radius>{r:.3f}</radius><length>{h:.3f}</length></cylinder>"
    pose = f"{cx:.3f} {cy:.3f} {h / 2:.3f} 0 0 0"
    out.append(f'        <collision name="{name}"><pose>{pose}</pose><geometry>{geom}</geometry></collision>')
    out.append(f'        <visual name="{name}"><pose>{pose}</pose><geometry>{geom}</geometry></visual>')
out.append("      </link>")
out.append("    </model>")
out.append("    <!-- The taxi, at the origin on the north-south avenue, facing south. -->")
out.append("    <include>")
out.append("      <uri>model://taxi_holo</uri>")
out.append("      <name>taxi_holo</name>")
out.append("      <pose>0 0 0 0 0 -1.5707963267948966</pose>")
out.append("    </include>")
out.append("  </world>")
out.append("</sdf>")
path = sys.argv[1] if len(sys.argv) > 1 else "cityLarge.world"
with open(path, "w") as f:
    f.write("\n".join(out) + "\n")
print(f"{path}: {len(boxes)} boxes, {len(cylinders)} cylinders")
