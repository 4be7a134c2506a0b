#!/usr/bin/env python3
"""Writes worlds/cityLarge.world: a 500 x 500 m city centred on the origin.

A grid of roads (12-16 m wide) between blocks of buildings (each block split into four
touching buildings of different heights), a perimeter road inside the city wall, a
106 m square plaza with a fountain, a round tower with a curved road around it, an L-shaped sharp bend, and
in the north-west a 14 m wide quarter-circle boulevard whose building edges are chains of
rotated boxes (backed by axis-aligned "staircase" buildings, so no closed pocket of free space
is left behind them).
Deterministic: rerun after editing and commit the result (the world is data a teacher reads).

Usage:
  make_city.py [PATH]           writes cityLarge (above) to worlds/cityLarge.world, or to PATH
  make_city.py --out FILE.world [--seed N] [--blocks N] [--road-width M] [--size M]
               [--start X,Y,YAW] [--destinations N]
                                writes a simpler generated city to FILE.world ("-": standard
                                output), world "city", model "city" with link "buildings":
    --size M         side of the square city, m, centred on the origin (default 300); the
                     perimeter wall (2 m thick, 4 m high) stands on its edge
    --blocks N       N x N blocks (default 3), separated by straight roads; a road also runs
                     round the city just inside the wall, so there are N + 1 roads each way
    --road-width M   width of every road, m (default 14, >= 5)
    --seed N         seeds how the blocks split into buildings (1 to 3 a side, touching) and
                     the buildings' heights (6 to 40 m) (default 1)
    --start X,Y,YAW  the taxi's pose (yaw in rad); default: facing +x at the centre of the
                     first intersection inside the city (the south-west crossing of two inner
                     roads; with one block, the south-west corner of the perimeter road). Its
                     4 x 2 m body must not touch a building or the wall.
    --destinations N the world declares N destinations (default 0, at most the crossings but
                     the start's), <aula:destination name="d1">X Y</aula:destination>...: crossings
                     of two roads (always free), drawn with the seed, not the start's own
  The taxi is <include>d as model://taxi_holo named taxi_holo, as in cityLarge. The same
  parameters and seed always give the same file; a comment in it lists them (name=value). A bad parameter:
  one line on stderr naming it, exit status 2. (TeleTaxi's map is cityLarge's: a generated city
  needs its own map from aula-mapgen.)
"""
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sdfgen import (WORLDS, Parser, UsageError, box, boxes_overlap, check_int_range, collision_and_visual,  # noqa: E402
                    corners, fail, finite, include, join_negative_values, num, parse_pose, physics, pose,
                    static_model_open, world_open, write_output)

PROG = "make_city.py"
TAXI_LENGTH_M, TAXI_WIDTH_M = 4.0, 2.0  # worlds/models/taxi_holo body box
WALL_THICKNESS_M, WALL_HEIGHT_M = 2.0, 4.0
HEIGHTS = [6, 9, 12, 15, 20, 25, 32, 40]
MIN_BLOCK_M = 8.0


def city_large():
    """The text of worlds/cityLarge.world (the original script, unchanged, in a function)."""
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
    out += world_open("cityLarge")
    out += city_model(boxes, cylinders)
    out.append("    <!-- The taxi, at the origin on the north-south avenue, facing south. -->")
    out += taxi_include(0, 0, "-1.5707963267948966")
    out.append("  </world>")
    out.append("</sdf>")
    return "\n".join(out) + "\n", f"{len(boxes)} boxes, {len(cylinders)} cylinders"


def city_model(boxes, cylinders):
    out = [physics("0.005")] + static_model_open("city", "buildings")
    for name, cx, cy, sx, sy, h, yaw in boxes:
        out += box(name, cx, cy, h / 2, sx, sy, h, yaw)
    for name, cx, cy, r, h in cylinders:
        geom = f"<cylinder><radius>{r:.3f}</radius><length>{h:.3f}</length></cylinder>"
        out += collision_and_visual(name, pose(cx, cy, h / 2), geom)
    out.append("      </link>")
    out.append("    </model>")
    return out


def taxi_include(x, y, yaw):
    return include("taxi_holo", "taxi_holo", x, y, yaw)


# ---- the generated city -------------------------------------------------------------------

def road_centres(size, blocks, road_width):
    """Centre lines of the N + 1 roads (the same along x and y) and the block side."""
    inner = size - 2 * WALL_THICKNESS_M
    block = (inner - (blocks + 1) * road_width) / blocks
    lo = -inner / 2
    return [lo + road_width / 2 + k * (block + road_width) for k in range(blocks + 1)], block


def split(rng, a0, a1):
    """Cuts [a0, a1] into 1 to 3 touching pieces (each >= 8 m where possible)."""
    most = max(1, min(3, int((a1 - a0) // MIN_BLOCK_M)))
    k = rng.randint(1, most)
    step = (a1 - a0) / k
    cuts = [a0] + [round(a0 + step * (m + rng.uniform(-0.2, 0.2)), 1) for m in range(1, k)] + [a1]
    return list(zip(cuts[:-1], cuts[1:]))


def generated_boxes(seed, blocks, road_width, size):
    rng = random.Random(seed)
    centres, block = road_centres(size, blocks, road_width)
    boxes = []
    for i in range(blocks):
        for j in range(blocks):
            x0, x1 = centres[i] + road_width / 2, centres[i + 1] - road_width / 2
            y0, y1 = centres[j] + road_width / 2, centres[j + 1] - road_width / 2
            k = 0
            for a0, a1 in split(rng, x0, x1):
                for b0, b1 in split(rng, y0, y1):
                    h = float(rng.choice(HEIGHTS))
                    boxes.append((f"block_{i}_{j}_{k}", (a0 + a1) / 2, (b0 + b1) / 2, a1 - a0, b1 - b0, h, 0.0))
                    k += 1
    half, t = size / 2, WALL_THICKNESS_M
    boxes.append(("wall_north", 0.0, half - t / 2, size, t, WALL_HEIGHT_M, 0.0))
    boxes.append(("wall_south", 0.0, -half + t / 2, size, t, WALL_HEIGHT_M, 0.0))
    boxes.append(("wall_east", half - t / 2, 0.0, t, size - 2 * t, WALL_HEIGHT_M, 0.0))
    boxes.append(("wall_west", -half + t / 2, 0.0, t, size - 2 * t, WALL_HEIGHT_M, 0.0))
    return boxes


def default_start(blocks, road_width, size):
    centres, _ = road_centres(size, blocks, road_width)
    c = centres[1] if blocks >= 2 else centres[0]
    return (c, c, 0.0)


def destinations(a, centres):
    """N road crossings drawn with the seed, farther than a block from the start (d1, d2...)."""
    rng = random.Random(a.seed * 7919 + 17)
    x, y, _ = a.start
    crossings = [(cx, cy) for cx in centres for cy in centres if math.hypot(cx - x, cy - y) > a.road_width]
    if a.destinations > len(crossings):
        raise UsageError(f"--destinations {a.destinations}: the city has {len(crossings)} crossings away from the start")
    chosen = rng.sample(crossings, a.destinations)
    return [f'    <aula:destination name="d{k + 1}">{num(cx)} {num(cy)}</aula:destination>' for k, (cx, cy) in enumerate(chosen)]


def generated_city(a):
    boxes = generated_boxes(a.seed, a.blocks, a.road_width, a.size)
    x, y, yaw = a.start
    taxi = corners(x, y, yaw, TAXI_LENGTH_M, TAXI_WIDTH_M)
    for name, cx, cy, sx, sy, h, byaw in boxes:
        if boxes_overlap(taxi, corners(cx, cy, byaw, sx, sy)):
            raise UsageError(f"--start: the taxi ({TAXI_LENGTH_M:g} x {TAXI_WIDTH_M:g} m) at ({x:g}, {y:g}, yaw {yaw:g})"
                             f" overlaps {name}")
    half_in = a.size / 2 - WALL_THICKNESS_M
    if any(abs(px) >= half_in or abs(py) >= half_in for px, py in taxi):
        raise UsageError(f"--start: the taxi at ({x:g}, {y:g}) is not inside the city wall (|x|, |y| < {half_in:g})")
    centres, block = road_centres(a.size, a.blocks, a.road_width)
    # (an XML comment cannot hold "--": name=value for each option)
    parameters = (f"seed={a.seed} blocks={a.blocks} road-width={num(a.road_width)} size={num(a.size)}"
                  f" start={num(x)},{num(y)},{num(yaw)}" + (f" destinations={a.destinations}" if a.destinations else ""))
    out = ['<?xml version="1.0"?>',
           f"<!-- city: a {num(a.size)} x {num(a.size)} m city centred on the origin, for the TeleTaxi exercise:",
           f"     {a.blocks} x {a.blocks} blocks of {block:.2f} m, {a.blocks + 1} roads each way {num(a.road_width)} m wide",
           f"     (centre lines at {', '.join(f'{c:.2f}' for c in centres)}), the outer ones just inside the wall.",
           "     Generated by worlds/tools/make_city.py; the same parameters give the same file.",
           f"     parameters: {parameters} -->"]
    out += world_open("city")
    out += destinations(a, centres)
    out += city_model(boxes, [])
    out.append(f"    <!-- The taxi, at ({num(x)}, {num(y)}), yaw {num(yaw)} rad. -->")
    out += taxi_include(x, y, num(yaw))
    out += ["  </world>", "</sdf>"]
    return "\n".join(out) + "\n", f"{len(boxes)} boxes"


# ---- command line -------------------------------------------------------------------------

VALUE_OPTIONS = ("--out", "--seed", "--blocks", "--road-width", "--size", "--start", "--destinations")


def parse_args(argv):
    p = Parser(prog=PROG, description="Writes a city world (see the module docstring).")
    p.add_argument("path", nargs="?", help="where to write cityLarge (default worlds/cityLarge.world)")
    p.add_argument("--out", help="write a generated city here ('-': standard output)")
    p.add_argument("--seed", type=int)
    p.add_argument("--blocks", type=int)
    p.add_argument("--road-width", type=finite)
    p.add_argument("--size", type=finite)
    p.add_argument("--start", type=parse_pose)
    p.add_argument("--destinations", type=int)
    a = p.parse_args(join_negative_values(argv, VALUE_OPTIONS))
    generated = [o for o in ("seed", "blocks", "road_width", "size", "start", "destinations") if getattr(a, o) is not None]
    if a.out is None:
        if generated:
            raise UsageError(f"--{generated[0].replace('_', '-')} needs --out (without --out: cityLarge)")
        return a
    if a.path is not None:
        raise UsageError(f"unexpected argument {a.path!r} with --out")
    a.seed = 1 if a.seed is None else a.seed
    a.blocks = 3 if a.blocks is None else a.blocks
    a.road_width = 14.0 if a.road_width is None else a.road_width
    a.size = 300.0 if a.size is None else a.size
    a.destinations = 0 if a.destinations is None else a.destinations
    check_int_range("destinations", a.destinations, 0, 100)
    check_int_range("blocks", a.blocks, 1, 50)
    if not a.road_width >= 5:
        raise UsageError(f"--road-width must be >= 5 m (the taxi is {TAXI_LENGTH_M:g} x {TAXI_WIDTH_M:g} m), got {a.road_width:g}")
    if not 0 < a.size <= 5000:
        raise UsageError(f"--size must be in (0, 5000] m, got {a.size:g}")
    _, block = road_centres(a.size, a.blocks, a.road_width)
    if block < MIN_BLOCK_M:
        raise UsageError(f"--size {a.size:g} is too small for --blocks {a.blocks} and --road-width {a.road_width:g}:"
                         f" blocks would be {block:.2f} m (need >= {MIN_BLOCK_M:g})")
    if a.start is None:
        a.start = default_start(a.blocks, a.road_width, a.size)
    return a


def main(argv):
    try:
        a = parse_args(argv)
        if a.out is None:
            path = a.path if a.path is not None else os.path.join(WORLDS, "cityLarge.world")
            text, summary = city_large()
        else:
            path = a.out
            text, summary = generated_city(a)
    except UsageError as e:
        return fail(PROG, e)
    return write_output(PROG, path, text, summary, what="")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
