#!/usr/bin/env python3
"""Which rooms of a generated house a vacuum run entered, and when (bench/vacuum_large_floors.sh).

Usage: vacuum_rooms.py HOUSE.world TRACE.json

HOUSE.world is make_house.py's (its header comment gives the room grid's lines); TRACE.json is
`aula run --trace`'s (the robot's true pose, sampled). A room is entered when the robot's centre
is 0.3 m inside its walls. Prints one line: "entered N of M rooms; first visits at T1 T2 ... s",
and "; never (i, j) ..." naming the rooms never entered (column i from the west, row j from the
south).
"""
import json
import re
import sys


def grid_lines(world_path):
    with open(world_path, encoding="utf-8") as f:
        head = f.read(4000)
    xs = re.search(r"column lines x = ([-0-9., ]+);", head)
    ys = re.search(r"row lines y = ([-0-9., ]+)\)", head)
    if not xs or not ys:
        sys.exit(f"{world_path}: no room grid in its header comment (is it make_house.py's?)")
    return [float(v) for v in xs.group(1).split(",")], [float(v) for v in ys.group(1).split(",")]


def poses(trace_path):
    with open(trace_path, encoding="utf-8") as f:
        trace = json.load(f)
    samples = trace["samples"]
    x = y = 0
    out = []
    for dx, dy in zip(samples["x_mm"], samples["y_mm"]):
        x += dx
        y += dy
        out.append((x / 1000.0, y / 1000.0))
    return samples["period_s"], out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    xs, ys = grid_lines(sys.argv[1])
    period_s, path = poses(sys.argv[2])
    inset_m = 0.3
    first = {}
    for k, (x, y) in enumerate(path):
        for i in range(len(xs) - 1):
            for j in range(len(ys) - 1):
                if (i, j) not in first and xs[i] + inset_m < x < xs[i + 1] - inset_m and ys[j] + inset_m < y < ys[j + 1] - inset_m:
                    first[(i, j)] = k * period_s
    rooms = (len(xs) - 1) * (len(ys) - 1)
    times = " ".join(f"{t:.0f}" for t in sorted(first.values()))
    never = " ".join(f"({i}, {j})" for i in range(len(xs) - 1) for j in range(len(ys) - 1) if (i, j) not in first)
    print(f"entered {len(first)} of {rooms} rooms; first visits at {times} s" + (f"; never {never}" if never else ""))


if __name__ == "__main__":
    main()
