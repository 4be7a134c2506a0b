#!/usr/bin/env python3
"""Writes a generated house for the Vacuum cleaner exercise, in the style of worlds/vacuum.world.

Usage:
  make_house.py --out FILE.world [--seed N] [--rooms-x N] [--rooms-y N] [--room-size M]
                [--door-width M] [--furniture N] [--start X,Y,YAW | --start-room I,J[,YAW]]
                [--step S | --no-physics]

  --out FILE.world  where to write ("-": standard output); required
  --seed N          seeds room sizes, doors and furniture (default 1)
  --rooms-x N       rooms along x (default 3, 1..20)
  --rooms-y N       rooms along y (default 2, 1..20)
  --room-size M     nominal room size, wall centre to wall centre (default 3.2, 2..10); each
                    column's width and each row's depth is it times 0.85..1.15 (seeded, cm)
  --door-width M    width of every door (default 0.9, >= 0.5 and small enough to leave 0.15 m
                    of wall each side in the smallest possible room)
  --furniture N     boxes per room (default 2, 0..20); a box that cannot be placed after 200
                    tries is left out (the header comment says how many were placed)
  --start X,Y,YAW   the roomba's pose (yaw in rad); default: the centre of room (0, 0) (the
                    south-west one), yaw 0; its 0.165 m disc must clear every wall by 0.085 m
  --start-room I,J[,YAW]
                    the roomba at the centre of room (I, J) (column I from the west, row J from
                    the south, from 0), heading YAW (rad, default 0); not with --start
  --step S          writes <physics type="dart"><max_step_size>S</max_step_size></physics>
                    (S in [0.0001, 0.05] s, what aula-sim accepts); without it no <physics> is
                    written (the simulator's configured step applies)
  --no-physics      the default (no <physics>), spelled out; not with --step

The world (named "house"): one static model "house" with link "walls" and link "furniture",
every collision a box with an identical visual, then
  <include><uri>model://roomba</uri><name>roomba</name><pose>X Y 0 0 0 YAW</pose></include>.
  - A grid of rooms-x by rooms-y rooms centred on the origin; room (i, j) is column i (from
    west) and row j (from south). Walls are 0.2 m thick and 2.5 m high, on the grid lines;
    outer walls wall_south, wall_north, wall_west, wall_east (no door to the outside).
  - Interior walls: wall_v<i>_<j> on the vertical line between columns i-1 and i in row j,
    wall_h<j>_<i> on the horizontal line between rows j-1 and j in column i; one with a door is
    two boxes, suffixes _a and _b. The doors form a random spanning tree of the rooms (every
    room reachable) plus, half of the time, one extra door (a loop).
  - Furniture: furniture_<i>_<j>_<k>, boxes 0.4..1.6 m a side, 0.4..2 m high, inside one room,
    not overlapping each other; never within 0.6 m in front of a door (on either side, the door
    width plus 0.1 m each side), never within 0.665 m of the start (0.5 m free around the
    roomba's disc), and never leaving a room's free space (where the roomba's centre can be
    with 0.085 m to spare, i.e. passages >= 0.5 m wide) in more than one piece, nor leaving a
    pocket where it would fit with 0.035 m to spare; so the roomba can reach every room, door
    and free corner from the start.
A header comment gives the extent, the doors, the furniture count and the parameters (as
name=value: an XML comment cannot hold "--"). The same
parameters and seed always give the same bytes. A bad parameter: one line on stderr naming it,
exit status 2. The coverage referee and the vacuum component read a map (Vacuum.Map): make one
for a generated house with aula-mapgen (like worlds/vacuum.world's in tools/mapgen).
"""
import argparse
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sdfgen import (Parser, UsageError, box, check_int_range, check_range, fail, finite, include,  # noqa: E402
                    join_negative_values, num, parse_pose, physics, static_model_open, world_open, write_output)

PROG = "make_house.py"

WALL_T = 0.2        # wall thickness, m
WALL_H = 2.5        # wall height, m
ROBOT_R = 0.165     # roomba radius, m
CLEAR_R = 0.25      # the roomba's centre stays this far from everything (radius + 0.085):
                    # every passage the generator relies on is >= 0.5 m wide
POCKET_R = 0.2      # and no pocket of floor where the roomba fits with 0.035 m to spare
START_FREE = 0.5    # free floor around the roomba's disc at the start
DOOR_MARGIN = 0.15  # wall left between a door and the perpendicular wall
DOOR_DEPTH = 0.6    # furniture-free depth in front of a door
JITTER = 0.15       # room sizes vary by +-15 %
GRID = 0.05         # cell of the reachability check, m
TRIES = 200         # placement attempts per furniture box


def box_xml(name, cx, cy, sx, sy, h):
    """A box standing on the floor, h high."""
    return box(name, cx, cy, h / 2, sx, sy, h)


def rect_point_distance(r, x, y):
    """Distance from (x, y) to the axis-aligned rectangle r = (x0, y0, x1, y1); 0 inside."""
    dx = max(r[0] - x, 0.0, x - r[2])
    dy = max(r[1] - y, 0.0, y - r[3])
    return math.hypot(dx, dy)


def rects_overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


class House:
    def __init__(self, a):
        self.a = a
        rng = random.Random(a.seed)
        self.rng = rng
        nx, ny = a.rooms_x, a.rooms_y
        widths = [round(a.room_size * rng.uniform(1 - JITTER, 1 + JITTER), 2) for _ in range(nx)]
        depths = [round(a.room_size * rng.uniform(1 - JITTER, 1 + JITTER), 2) for _ in range(ny)]
        self.xs = self.lines(widths)
        self.ys = self.lines(depths)
        self.doors = self.choose_doors()
        self.walls = self.build_walls()
        if a.start is not None:
            self.start = a.start
        else:
            i, j, yaw = a.start_room if a.start_room is not None else (0, 0, 0.0)
            if not (0 <= i < nx and 0 <= j < ny):
                raise UsageError(f"--start-room {i},{j}: the house has rooms 0..{nx - 1} x 0..{ny - 1}")
            self.start = self.room_centre(i, j) + (yaw,)
        self.check_start()
        self.furniture, self.placed = self.place_furniture()

    @staticmethod
    def lines(sizes):
        total = round(sum(sizes), 2)
        out = [round(-total / 2, 2)]
        for s in sizes:
            out.append(round(out[-1] + s, 2))
        return out

    def interior(self, i, j):
        """The free floor of room (i, j): (x0, y0, x1, y1), between the walls' faces."""
        h = WALL_T / 2
        return (self.xs[i] + h, self.ys[j] + h, self.xs[i + 1] - h, self.ys[j + 1] - h)

    def room_centre(self, i, j):
        r = self.interior(i, j)
        return ((r[0] + r[2]) / 2, (r[1] + r[3]) / 2)

    def choose_doors(self):
        """A random spanning tree of the room grid (depth first), maybe one extra edge.

        A door: (room, room, centre along the wall), rooms as (i, j), the first the west or south one.
        """
        rng, nx, ny = self.rng, self.a.rooms_x, self.a.rooms_y

        def neighbours(i, j):
            return [(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
                    if 0 <= i + di < nx and 0 <= j + dj < ny]

        seen, stack, edges = {(0, 0)}, [(0, 0)], []
        while stack:
            room = stack[-1]
            fresh = [n for n in neighbours(*room) if n not in seen]
            if not fresh:
                stack.pop()
                continue
            nxt = rng.choice(fresh)
            seen.add(nxt)
            edges.append(tuple(sorted((room, nxt))))
            stack.append(nxt)
        all_edges = sorted({tuple(sorted((r, n))) for r in ((i, j) for i in range(nx) for j in range(ny))
                            for n in neighbours(*r)})
        spare = [e for e in all_edges if e not in edges]
        if spare and rng.random() < 0.5:
            edges.append(rng.choice(spare))
        doors = []
        dw = self.a.door_width
        for r0, r1 in edges:
            if r0[1] == r1[1]:  # side by side: a door in a vertical wall, along y
                lo, hi = self.interior(*r0)[1], self.interior(*r0)[3]
            else:               # one above the other: a door in a horizontal wall, along x
                lo, hi = self.interior(*r0)[0], self.interior(*r0)[2]
            c = round(rng.uniform(lo + DOOR_MARGIN + dw / 2, hi - DOOR_MARGIN - dw / 2), 2)
            doors.append((r0, r1, c))
        return doors

    def door_between(self, r0, r1):
        for d in self.doors:
            if d[0] == r0 and d[1] == r1:
                return d
        return None

    def build_walls(self):
        """(name, x0, y0, x1, y1) rectangles."""
        xs, ys, nx, ny, h = self.xs, self.ys, self.a.rooms_x, self.a.rooms_y, WALL_T / 2
        walls = [("wall_south", xs[0] - h, ys[0] - h, xs[-1] + h, ys[0] + h),
                 ("wall_north", xs[0] - h, ys[-1] - h, xs[-1] + h, ys[-1] + h),
                 ("wall_west", xs[0] - h, ys[0] + h, xs[0] + h, ys[-1] - h),
                 ("wall_east", xs[-1] - h, ys[0] + h, xs[-1] + h, ys[-1] - h)]
        hw = self.a.door_width / 2

        def add(name, door, lo, hi, make):
            if door is None:
                walls.append((name,) + make(lo, hi))
            else:
                walls.append((name + "_a",) + make(lo, door[2] - hw))
                walls.append((name + "_b",) + make(door[2] + hw, hi))

        # Vertical walls span the rooms' depth; horizontal ones also cover the junctions.
        for i in range(1, nx):
            for j in range(ny):
                add(f"wall_v{i}_{j}", self.door_between((i - 1, j), (i, j)), ys[j] + h, ys[j + 1] - h,
                    lambda lo, hi, x=xs[i]: (x - h, lo, x + h, hi))
        for j in range(1, ny):
            for i in range(nx):
                lo = xs[i] - h if i > 0 else xs[0] + h
                add(f"wall_h{j}_{i}", self.door_between((i, j - 1), (i, j)), lo, xs[i + 1] - h,
                    lambda lo, hi, y=ys[j]: (lo, y - h, hi, y + h))
        return walls

    def door_zones(self, i, j):
        """Furniture-free rectangles in front of room (i, j)'s doors, and a probe point in each."""
        out = []
        hw, h = self.a.door_width / 2 + 0.1, WALL_T / 2
        for r0, r1, c in self.doors:
            if (i, j) not in (r0, r1):
                continue
            if r0[1] == r1[1]:  # vertical wall at x = xs[r1[0]]
                x = self.xs[r1[0]]
                sign = 1 if (i, j) == r1 else -1  # into this room
                face = x + sign * h
                rect = (min(face, face + sign * DOOR_DEPTH), c - hw, max(face, face + sign * DOOR_DEPTH), c + hw)
                probe = (face + sign * DOOR_DEPTH / 2, c)
            else:               # horizontal wall at y = ys[r1[1]]
                y = self.ys[r1[1]]
                sign = 1 if (i, j) == r1 else -1
                face = y + sign * h
                rect = (c - hw, min(face, face + sign * DOOR_DEPTH), c + hw, max(face, face + sign * DOOR_DEPTH))
                probe = (c, face + sign * DOOR_DEPTH / 2)
            out.append((rect, probe))
        return out

    def check_start(self):
        x, y, _ = self.start
        xs, ys = self.xs, self.ys
        if not (xs[0] < x < xs[-1] and ys[0] < y < ys[-1]):
            raise UsageError(f"--start ({x:g}, {y:g}) is outside the house (x {xs[0]:g}..{xs[-1]:g},"
                             f" y {ys[0]:g}..{ys[-1]:g})")
        for name, *r in self.walls:
            if rect_point_distance(r, x, y) < CLEAR_R:
                raise UsageError(f"--start ({x:g}, {y:g}): the roomba (radius {ROBOT_R:g} m) needs"
                                 f" {CLEAR_R - ROBOT_R:.3f} m from the walls; it touches {name}")

    def place_furniture(self):
        rng, a = self.rng, self.a
        sx0, sy0, _ = self.start
        keep_off = ROBOT_R + START_FREE
        boxes, placed = [], 0
        for j in range(a.rooms_y):
            for i in range(a.rooms_x):
                room = self.interior(i, j)
                zones = self.door_zones(i, j)
                probes = [p for _, p in zones]
                if room[0] <= sx0 <= room[2] and room[1] <= sy0 <= room[3]:
                    probes.append((sx0, sy0))
                grids = [Reach(room, probes, CLEAR_R), Reach(room, probes, POCKET_R)]
                mine = []
                for k in range(a.furniture):
                    for _ in range(TRIES):
                        w = round(rng.uniform(0.4, 1.6), 2)
                        d = round(rng.uniform(0.4, 1.6), 2)
                        height = round(rng.uniform(0.4, 2.0), 2)
                        if w > room[2] - room[0] or d > room[3] - room[1]:
                            continue
                        x0 = round(rng.uniform(room[0], room[2] - w), 2)
                        y0 = round(rng.uniform(room[1], room[3] - d), 2)
                        r = (max(x0, room[0]), max(y0, room[1]), min(x0 + w, room[2]), min(y0 + d, room[3]))
                        if any(rects_overlap(r, m[1]) for m in mine):
                            continue
                        if any(rects_overlap(r, z) for z, _ in zones):
                            continue
                        if rect_point_distance(r, sx0, sy0) < keep_off:
                            continue
                        if not all(g.still_connected(r) for g in grids):
                            continue
                        for g in grids:
                            g.block(r)
                        mine.append((f"furniture_{i}_{j}_{k}", r, height))
                        placed += 1
                        break
                boxes += mine
        return boxes, placed

    def xml(self, parameters):
        a, xs, ys = self.a, self.xs, self.ys
        x, y, yaw = self.start
        h = WALL_T / 2
        door_text = ", ".join(f"({r0[0]},{r0[1]})-({r1[0]},{r1[1]})" for r0, r1, _ in self.doors)
        requested = a.furniture * a.rooms_x * a.rooms_y
        out = ['<?xml version="1.0"?>',
               f"<!-- house: a generated house for the Vacuum cleaner exercise (worlds/tools/make_house.py). Outer",
               f"     walls 0.2 m thick and 2.5 m high, extent x [{xs[0] - h:.2f}, {xs[-1] + h:.2f}], y [{ys[0] - h:.2f},"
               f" {ys[-1] + h:.2f}]; {a.rooms_x} x {a.rooms_y} rooms",
               f"     (column lines x = {', '.join(f'{v:.2f}' for v in xs)}; row lines y = {', '.join(f'{v:.2f}' for v in ys)})",
               f"     joined by {len(self.doors)} doors {num(a.door_width)} m wide: {door_text or 'none'}; no door to the outside.",
               f"     {self.placed} of {requested} furniture boxes placed; all stand on the floor and block the robot.",
               f"     The roomba starts at ({num(x)}, {num(y)}), yaw {num(yaw)}.",
               f"     parameters: {parameters} -->"]
        out += world_open("house")
        if a.step is not None:
            out.append(physics(num(a.step)))
        out += static_model_open("house", "walls")
        for name, x0, y0, x1, y1 in self.walls:
            out += box_xml(name, (x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0, WALL_H)
        out.append('      </link>')
        out.append('      <link name="furniture">')
        for name, r, height in self.furniture:
            out += box_xml(name, (r[0] + r[2]) / 2, (r[1] + r[3]) / 2, r[2] - r[0], r[3] - r[1], height)
        out += ['      </link>', '    </model>']
        out += include("roomba", "roomba", x, y, num(yaw))
        out += ['  </world>', '</sdf>', '']
        return "\n".join(out)


class Reach:
    """Where the roomba's centre can be in one room (cells GRID wide, clear by `clear` of the
    walls' faces and of furniture), to keep that space in one piece holding every probe."""

    def __init__(self, room, probes, clear):
        self.room, self.clear = room, clear
        self.nx = max(1, int((room[2] - room[0]) / GRID))
        self.ny = max(1, int((room[3] - room[1]) / GRID))
        self.cx = [room[0] + (a + 0.5) * (room[2] - room[0]) / self.nx for a in range(self.nx)]
        self.cy = [room[1] + (b + 0.5) * (room[3] - room[1]) / self.ny for b in range(self.ny)]
        self.free = set()
        for a, x in enumerate(self.cx):
            for b, y in enumerate(self.cy):
                if min(x - room[0], room[2] - x, y - room[1], room[3] - y) >= clear:
                    self.free.add((a, b))
        self.probes = [self.cell(*p) for p in probes]

    def cell(self, x, y):
        a = min(self.nx - 1, max(0, int((x - self.room[0]) / (self.room[2] - self.room[0]) * self.nx)))
        b = min(self.ny - 1, max(0, int((y - self.room[1]) / (self.room[3] - self.room[1]) * self.ny)))
        return a, b

    def blocked_by(self, r):
        out = set()
        a0, b0 = self.cell(r[0] - self.clear, r[1] - self.clear)
        a1, b1 = self.cell(r[2] + self.clear, r[3] + self.clear)
        for a in range(a0, a1 + 1):
            for b in range(b0, b1 + 1):
                if (a, b) in self.free and rect_point_distance(r, self.cx[a], self.cy[b]) < self.clear:
                    out.add((a, b))
        return out

    def still_connected(self, r):
        free = self.free - self.blocked_by(r)
        if not free:
            return False
        if any(p not in free for p in self.probes):
            return False
        seed = self.probes[0] if self.probes else min(free)
        seen, todo = {seed}, [seed]
        while todo:
            a, b = todo.pop()
            for n in ((a + 1, b), (a - 1, b), (a, b + 1), (a, b - 1)):
                if n in free and n not in seen:
                    seen.add(n)
                    todo.append(n)
        return len(seen) == len(free)

    def block(self, r):
        self.free -= self.blocked_by(r)


# ---- command line -------------------------------------------------------------------------

VALUE_OPTIONS = ("--out", "--seed", "--rooms-x", "--rooms-y", "--room-size", "--door-width", "--furniture",
                 "--start", "--start-room", "--step")


def parse_room(text):
    """argparse type: "I,J" or "I,J,YAW" -> (i, j, yaw)."""
    parts = text.split(",")
    try:
        room = (int(parts[0]), int(parts[1]), float(parts[2]) if len(parts) == 3 else 0.0)
    except (ValueError, IndexError):
        room = None
    if room is None or len(parts) not in (2, 3) or not math.isfinite(room[2]):
        raise argparse.ArgumentTypeError(f"expected I,J or I,J,YAW (whole numbers, then a number), got {text!r}")
    return room


def parse_args(argv):
    p = Parser(prog=PROG, description="Writes a generated house (see the module docstring).")
    p.add_argument("--out", required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rooms-x", type=int, default=3)
    p.add_argument("--rooms-y", type=int, default=2)
    p.add_argument("--room-size", type=finite, default=3.2)
    p.add_argument("--door-width", type=finite, default=0.9)
    p.add_argument("--furniture", type=int, default=2)
    start = p.add_mutually_exclusive_group()
    start.add_argument("--start", type=parse_pose)
    start.add_argument("--start-room", type=parse_room)
    physics = p.add_mutually_exclusive_group()
    physics.add_argument("--step", type=finite)
    physics.add_argument("--no-physics", action="store_true")
    a = p.parse_args(join_negative_values(argv, VALUE_OPTIONS))
    check_int_range("rooms-x", a.rooms_x, 1, 20)
    check_int_range("rooms-y", a.rooms_y, 1, 20)
    check_range("room-size", a.room_size, 2.0, 10.0, "m")
    widest_door = round(a.room_size * (1 - JITTER) - WALL_T - 2 * DOOR_MARGIN, 2) - 0.01
    if not 0.5 <= a.door_width <= widest_door:
        raise UsageError(f"--door-width must be in [0.5, {widest_door:.2f}] m for --room-size {a.room_size:g},"
                         f" got {a.door_width:g}")
    check_int_range("furniture", a.furniture, 0, 20)
    if a.step is not None:
        check_range("step", a.step, 0.0001, 0.05, "s")
    return a


def main(argv):
    try:
        a = parse_args(argv)
        house = House(a)
    except UsageError as e:
        return fail(PROG, e)
    x, y, yaw = house.start
    # (an XML comment cannot hold "--": name=value for each option)
    parameters = (f"seed={a.seed} rooms-x={a.rooms_x} rooms-y={a.rooms_y} room-size={num(a.room_size)}"
                  f" door-width={num(a.door_width)} furniture={a.furniture} start={num(x)},{num(y)},{num(yaw)}"
                  + (f" step={num(a.step)}" if a.step is not None else ""))
    return write_output(PROG, a.out, house.xml(parameters),
                        f"{a.rooms_x} x {a.rooms_y} rooms, {len(house.doors)} doors,"
                        f" {house.placed} furniture boxes, roomba at ({num(x)}, {num(y)})")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
