#!/usr/bin/env python3
"""Writes the Autopark streets: worlds/autopark.world and its slot-size variants.

A road along x from -25 to 35; 0.2 m curbs with faces at y = -4.25 (parking side) and y = +5;
parked cars (4.9 x 2.2 m boxes, the outline RoboticsAcademy's `opel` mesh shows the lasers)
centred at y = -3, at RA's x positions. The free slot starts at the front bumper of the car at
x = 0.5 (x = 2.95) and is `slot_m` long; the cars beyond it move with it. The curbs are below
the lasers' plane (0.5 m, the car model's), so no beam sees them, as on RA's curb-less street;
they stay for the referee's curb distance and to keep the car on the road. The ideal
parked pose is the slot's centre, y = -3, yaw 0. The car ("car", model taxi_holo_laser) starts
at (-7, 2.5) facing +x.

  autopark.world                     RA's street: an 8.6 m slot (2.15 car lengths) between
                                     the cars at x = 0.5 and 14, the car turns in place ("diff",
                                     like the original)
  autopark_ackermann.world           the same street, car-like kinematics (R = 5 m)
  autopark_ackermann_<k>L.world      slots of k = 1.6, 1.4, 1.3, 1.2 car lengths (4 m), car-like

The car model is written inline (from worlds/models/taxi_holo_laser/model.sdf) so a variant can
change its kinematics. Deterministic: rerun after editing and commit the result.

Usage:
  make_autopark.py              rewrites the shipped worlds above (and only those)
  make_autopark.py --out FILE.world [--slot-length M] [--slot-x M] [--curb-offset M]
                   [--kinematics diff|ackermann] [--start X,Y[,YAW]]
                                writes one street to FILE.world ("-": standard output):
    --slot-length M   free slot length, m (default 8.6 = 2.15 car lengths); must be > 2.6 m, the
                      widest gap between the other parked cars, since the referee takes the
                      widest gap as the slot
    --slot-x M        x of the slot's start, the front bumper of the car before it (default
                      2.95); every parked car moves with it, same spacing; the road and its end
                      walls grow (never shrink below x -25..35) to keep all cars and the start
                      on the road
    --curb-offset M   how far the parking-side curb and the parked cars move away from the road
                      centre, in -y (default 0; >= -2, so the lane stays >= 5 m wide)
    --kinematics K    "diff" (default, turns in place) or "ackermann" (car-like)
    --start X,Y,YAW   the car's start pose (default -7,2.5,0; yaw in rad, 0 = facing +x); its
                      4 x 2 m body must not touch a curb or a parked car
    --reversed        the start faces -x (yaw pi): the parked cars on the car's left, the slot
                      behind it
    --rear-neighbour K, --front-neighbour K
                      the parked cars either side of the slot: "car" (default, 4.9 x 2.2 m),
                      "van" (5.5 x 2.0 m) or "small" (3.6 x 1.6 m); each keeps the cars' 0.15 m
                      from the curb, the slot stays --slot-length, and the cars beyond move
                      with the neighbour's length
    --free-curb M     a free curb M metres long beyond the last parked car before the east end
                      wall (default: the road's own end, 3.55 m at least); a car parked there
                      is not in the slot
  The names stay those of the shipped streets: parked_car_<i> (static includes), the collision
  curb_parking_side, the car model "car" (the referee finds the curb and the cars from the
  geometry; the names are for people). A comment in the world lists the parameters used, as
  name=value (an XML comment cannot hold "--").
  A bad parameter: one line on stderr naming it, exit status 2.
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sdfgen import (WORLDS, Parser, UsageError, box, boxes_overlap, check_range, corners, fail, finite,  # noqa: E402
                    include, join_negative_values, num, parse_pose, physics, static_model_open, world_open,
                    write_file, write_output)

CAR_LENGTH_M = 4.0
SLOT_START_X = 2.95  # front bumper of the parked car at x = 0.5
DEFAULT_SLOT_M = 8.6  # to the rear bumper of the car at x = 14, as on RA's street
PARKED_BEFORE = [-20.0, -13.5, -7.0, 0.5]
PARKED_AFTER_OFFSETS = [0.0, 7.5, 15.0]  # the default street: cars at 14, 21.5, 29
PARKED_HALF_LENGTH = 2.45  # RA's opel mesh: about 4.9 x 2.2 m
PARKED_HALF_WIDTH = 1.1
PARKED_Y = -3.0
# The neighbours a slot can have, (length, width, height) m; each stands 0.15 m off the curb as a car does.
NEIGHBOURS = {"car": (4.9, 2.2, 1.5), "van": (5.5, 2.0, 2.2), "small": (3.6, 1.6, 1.4)}
CURB_FACE_Y = -4.25   # parking-side curb face (its box: 1 m deep, 0.2 m high)
CURB_CLEARANCE_M = PARKED_Y - PARKED_HALF_WIDTH - CURB_FACE_Y  # 0.15: a parked car's side to the curb face
FAR_CURB_FACE_Y = 5.0
FAR_SIDE_HEIGHT_M = 1.0  # above the lasers: the far side of the road is seen, as the end walls are
ROAD_WEST, ROAD_EAST = -25.0, 35.0  # the default road; a street never gets shorter
WIDEST_OTHER_GAP_M = 2.6  # between the parked cars after the slot (7.5 - 4.9)
DEFAULT_START = (-7.0, 2.5, 0.0)
PROG = "make_autopark.py"


def street_box(name, x, y, z, sx, sy, sz):
    return box(name, x, y, z, sx, sy, sz, size_digits=2)


def car_text():
    with open(os.path.join(WORLDS, "models", "taxi_holo_laser", "model.sdf")) as f:
        return f.read()


def car_size():
    """(length, width) of the car's body box, from the model."""
    m = re.search(r"<collision name=\"body\">.*?<size>([\d.]+) ([\d.]+) [\d.]+</size>", car_text(), re.S)
    return float(m.group(1)), float(m.group(2))


def car_model(kinematics, start=DEFAULT_START):
    text = car_text()
    x, y, yaw = start
    model = re.search(r"<model name=\"taxi_holo_laser\">.*</model>", text, re.S).group(0)
    model = model.replace("<model name=\"taxi_holo_laser\">",
                          f"<model name=\"car\">\n    <pose>{num(x)} {num(y)} 0 0 0 {num(yaw)}</pose>")
    model = re.sub(r"<kinematics>\w+</kinematics>", f"<kinematics>{kinematics}</kinematics>", model)
    return "    " + model.replace("\n", "\n  ") + "\n"


def parked_xs(slot_m, slot_x, rear="car", front="car"):
    """The parked cars' centres along x; the neighbours either side of the slot may be longer or
    shorter than a car, and the cars beyond them move by the difference."""
    rear_extra = NEIGHBOURS[rear][0] / 2 - PARKED_HALF_LENGTH
    front_extra = NEIGHBOURS[front][0] / 2 - PARKED_HALF_LENGTH
    if slot_x == SLOT_START_X and rear == "car":
        before = list(PARKED_BEFORE)
    else:
        before = [slot_x + (x - SLOT_START_X) - 2 * rear_extra for x in PARKED_BEFORE]
        before[-1] += rear_extra  # the neighbour itself: its front bumper stays at slot_x
    after_first = slot_x + slot_m + PARKED_HALF_LENGTH
    after = [after_first + d + 2 * front_extra for d in PARKED_AFTER_OFFSETS]
    after[0] -= front_extra
    return before + after


def parked_kinds(rear="car", front="car"):
    """The kind of each car of parked_xs(), in the same order."""
    kinds = ["car"] * (len(PARKED_BEFORE) + len(PARKED_AFTER_OFFSETS))
    kinds[len(PARKED_BEFORE) - 1] = rear
    kinds[len(PARKED_BEFORE)] = front
    return kinds


def parked_y(kind, curb_offset):
    """A parked car's centre y: its side CURB_CLEARANCE_M off the curb face."""
    return CURB_FACE_Y - curb_offset + CURB_CLEARANCE_M + NEIGHBOURS[kind][1] / 2


def road_extent(parked, start, free_curb=None):
    """The road's x range: the default one, grown to keep every car and the start on it; with
    free_curb, the east end that far beyond the last car."""
    west = min(ROAD_WEST, min(parked) - PARKED_HALF_LENGTH - 2.55)
    east = max(ROAD_EAST, max(parked) + PARKED_HALF_LENGTH + 3.55)
    if free_curb is not None:
        east = max(parked) + PARKED_HALF_LENGTH + free_curb
    if start is not None:
        length, width = car_size()
        xs = [p[0] for p in corners(start[0], 0.0, start[2], length, width)]
        west = min(west, min(xs) - 3.0)
        east = max(east, max(xs) + 3.0)
    return float(math.floor(west + 1e-9)), float(east if free_curb is not None else math.ceil(east - 1e-9))  # no float dust


def parked_model(name, kind, x, y):
    """A parked car: the shared model for a car, an inline static box for a van or a small car."""
    if kind == "car":
        return include("parked_car", name, x, y, "0")
    length, width, height = NEIGHBOURS[kind]
    return ([f'    <model name="{name}">', "      <static>true</static>",
             f"      <pose>{num(x)} {num(y)} 0 0 0 0</pose>", '      <link name="body">']
            + box("body", 0, 0, height / 2, length, width, height) + ['      </link>', '    </model>'])


def world(slot_m, kinematics, title, slot_x=SLOT_START_X, curb_offset=0.0, start=DEFAULT_START,
          parameters=None, rear="car", front="car", free_curb=None):
    parked = parked_xs(slot_m, slot_x, rear, front)
    kinds = parked_kinds(rear, front)
    west, east = road_extent(parked, start, free_curb)
    car_y = PARKED_Y - curb_offset
    curb_face = CURB_FACE_Y - curb_offset
    ideal_x = slot_x + slot_m / 2.0
    ideal_y = (parked_y(rear, curb_offset) + parked_y(front, curb_offset)) / 2  # as the referee takes it
    sx, sy, syaw = start
    facing = "facing +x" if syaw == 0 else f"with yaw {num(syaw)} rad"
    out = ['<?xml version="1.0"?>',
           f"<!-- {title}: generated by worlds/tools/make_autopark.py, edit that and rerun.",
           f"     Road along x from {num(west)} to {num(east)}; the parking side's curb is a 0.2 m high box, face at"
           f" y = {num(curb_face)}",
           f"     (below the lasers), the far side a 1 m wall, face at y = +5; parked cars ({num(2 * PARKED_HALF_LENGTH)} x {num(2 * PARKED_HALF_WIDTH)} m) centred at y = {num(car_y)} leave a {slot_m:.2f} m slot",
           f"     ({slot_m / CAR_LENGTH_M:.2f} car lengths) between x = {slot_x:.2f} and {slot_x + slot_m:.2f};"
           f" ideal parked pose ({ideal_x:.2f}, {num(ideal_y)}), yaw 0.",
           f"     The car starts at ({num(sx)}, {num(sy)}) {facing}; kinematics \"{kinematics}\". -->"]
    if rear != "car" or front != "car":
        out.append(f"<!-- neighbours: a {rear} behind the slot, a {front} ahead of it"
                   f" ({', '.join(f'{k} {num(v[0])} x {num(v[1])} m' for k, v in NEIGHBOURS.items())}) -->")
    if free_curb is not None:
        out.append(f"<!-- a free curb of {num(free_curb)} m beyond the last parked car (not the slot) -->")
    if parameters is not None:
        out.append(f"<!-- parameters: {parameters} -->")
    out += world_open("autopark") + [physics("0.005")] + static_model_open("street", "curbs")
    mid, length = (west + east) / 2.0, east - west
    # End walls: from the parking-side curb's back (face - 1 m) to the far curb's back (face + 1 m).
    wall_y0, wall_y1 = curb_face - 1.0, FAR_CURB_FACE_Y + 1.0
    out += street_box("curb_parking_side", mid, curb_face - 0.5, 0.1, length, 1.0, 0.2)
    # The far side: a 1 m wall, not a curb, so the lasers (0.5 m up) see where the road ends there
    # (a car turning round needs to); the parking side's curb stays below them.
    out += street_box("curb_far_side", mid, FAR_CURB_FACE_Y + 0.5, FAR_SIDE_HEIGHT_M / 2, length, 1.0, FAR_SIDE_HEIGHT_M)
    out += street_box("end_wall_west", west - 0.5, (wall_y0 + wall_y1) / 2, 0.5, 1.0, wall_y1 - wall_y0, 1.0)
    out += street_box("end_wall_east", east + 0.5, (wall_y0 + wall_y1) / 2, 0.5, 1.0, wall_y1 - wall_y0, 1.0)
    out += ['      </link>', '    </model>']
    for i, (x, kind) in enumerate(zip(parked, kinds)):
        if x + PARKED_HALF_LENGTH > east or x - PARKED_HALF_LENGTH < west:
            continue  # beyond an end wall (never, the road grows)
        out += parked_model(f"parked_car_{i}", kind, x, parked_y(kind, curb_offset))
    out.append(car_model(kinematics, start).rstrip("\n"))
    out += ['  </world>', '</sdf>', '']
    return "\n".join(out)


def write_shipped():
    variants = [("autopark.world", DEFAULT_SLOT_M, "diff", "autopark"),
                ("autopark_ackermann.world", DEFAULT_SLOT_M, "ackermann", "autopark_ackermann")]
    for k in (1.6, 1.4, 1.3, 1.2):
        variants.append((f"autopark_ackermann_{k}L.world", k * CAR_LENGTH_M, "ackermann", f"autopark_ackermann_{k}L"))
    for filename, slot_m, kinematics, title in variants:
        write_file(os.path.join(WORLDS, filename), world(slot_m, kinematics, title))
        print(f"{filename}: slot {slot_m:.2f} m, {kinematics}")


# ---- command line -------------------------------------------------------------------------

VALUE_OPTIONS = ("--out", "--slot-length", "--slot-x", "--curb-offset", "--kinematics", "--start", "--rear-neighbour",
                 "--front-neighbour", "--free-curb")


def parse_args(argv):
    p = Parser(prog=PROG, description="Writes an Autopark street (see the module docstring).")
    p.add_argument("--out", required=True, help="the world file to write ('-': standard output)")
    p.add_argument("--slot-length", type=finite, default=DEFAULT_SLOT_M)
    p.add_argument("--slot-x", type=finite, default=SLOT_START_X)
    p.add_argument("--curb-offset", type=finite, default=0.0)
    p.add_argument("--kinematics", choices=("diff", "ackermann"), default="diff")
    p.add_argument("--start", type=parse_pose, default=None)
    p.add_argument("--reversed", action="store_true")
    p.add_argument("--rear-neighbour", choices=tuple(NEIGHBOURS), default="car")
    p.add_argument("--front-neighbour", choices=tuple(NEIGHBOURS), default="car")
    p.add_argument("--free-curb", type=finite, default=None)
    a = p.parse_args(join_negative_values(argv, VALUE_OPTIONS))
    if a.reversed and a.start is not None:
        raise UsageError("--reversed and --start: give the start's yaw in --start instead")
    if a.start is None:
        a.start = (DEFAULT_START[0], DEFAULT_START[1], math.pi if a.reversed else DEFAULT_START[2])
    if a.free_curb is not None:
        check_range("free-curb", a.free_curb, 0.0, 1000.0, "m")
    if not a.slot_length > WIDEST_OTHER_GAP_M:
        raise UsageError(f"--slot-length must be > {WIDEST_OTHER_GAP_M:g} m (the widest gap between the other"
                         f" parked cars; the referee takes the widest gap as the slot), got {a.slot_length:g}")
    if a.slot_length > 1000 or abs(a.slot_x) > 1000:
        raise UsageError("--slot-length and --slot-x must stay within 1000 m")
    check_range("curb-offset", a.curb_offset, -2.0, 100.0, "m", " (the lane must stay >= 5 m wide)")
    check_start(a)
    return a


def check_start(a):
    x, y, yaw = a.start
    if abs(x) > 1000:
        raise UsageError(f"--start x must stay within 1000 m, got {x:g}")
    length, width = car_size()
    car = corners(x, y, yaw, length, width)
    ys = [c[1] for c in car]
    curb_face = CURB_FACE_Y - a.curb_offset
    if min(ys) <= curb_face or max(ys) >= FAR_CURB_FACE_Y:
        raise UsageError(f"--start: the car ({length:g} x {width:g} m) at ({x:g}, {y:g}, yaw {yaw:g}) is not on the"
                         f" road between the curbs (y {curb_face:g} .. {FAR_CURB_FACE_Y:g})")
    kinds = parked_kinds(a.rear_neighbour, a.front_neighbour)
    for i, px in enumerate(parked_xs(a.slot_length, a.slot_x, a.rear_neighbour, a.front_neighbour)):
        length, width, _ = NEIGHBOURS[kinds[i]]
        parked = corners(px, parked_y(kinds[i], a.curb_offset), 0.0, length, width)
        if boxes_overlap(car, parked):
            raise UsageError(f"--start: the car at ({x:g}, {y:g}, yaw {yaw:g}) overlaps parked_car_{i} at x = {px:g}")


def main(argv):
    if not argv:
        write_shipped()
        return 0
    try:
        a = parse_args(argv)
    except UsageError as e:
        return fail(PROG, e)
    x, y, yaw = a.start
    # (an XML comment cannot hold "--": name=value for each option)
    parameters = (f"slot-length={num(a.slot_length)} slot-x={num(a.slot_x)} curb-offset={num(a.curb_offset)}"
                  f" kinematics={a.kinematics} start={num(x)},{num(y)},{num(yaw)}"
                  f" rear-neighbour={a.rear_neighbour} front-neighbour={a.front_neighbour}"
                  + ("" if a.free_curb is None else f" free-curb={num(a.free_curb)}"))
    title = "autopark" if a.out == "-" else os.path.splitext(os.path.basename(a.out))[0]
    title = re.sub(r"-{2,}", "-", title)  # it goes in an XML comment
    text = world(a.slot_length, a.kinematics, title, a.slot_x, a.curb_offset, a.start, parameters, a.rear_neighbour,
                 a.front_neighbour, a.free_curb)
    return write_output(PROG, a.out, text, f"slot {a.slot_length:.2f} m at x = {a.slot_x:.2f},"
                                           f" curb offset {a.curb_offset:g} m, {a.kinematics}")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
