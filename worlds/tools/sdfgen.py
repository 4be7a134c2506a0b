"""What the world generators in this folder share (make_autopark.py, make_city.py, make_house.py).

Not a script: each generator imports it from its own folder. Standard library only.

  SDF text     num, pose, box_geometry, collision_and_visual, box, include, world_open,
               physics, static_model_open
  geometry     corners, boxes_overlap (2-D boxes, for "does the start pose touch anything")
  command line UsageError, Parser, finite, parse_pose, join_negative_values, check_int_range,
               check_range, fail, write_file, write_output

Every generator prints a bad parameter as one line on stderr, "<script>: error: <what>", and
exits with status 2; the helpers here raise UsageError (or return 2 after printing) for that.
"""
import argparse
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
WORLDS = os.path.dirname(HERE)


# ---- SDF text -----------------------------------------------------------------------------

def num(v):
    """Shortest readable form: 14.0 -> "14", -13.5 -> "-13.5", 0.45000000001 -> "0.45"."""
    v = round(v, 9) + 0.0  # + 0.0 turns -0.0 into 0.0
    return f"{v:.12g}"


def pose(x, y, z, yaw=None):
    """The text of a <pose>: position in m with 3 decimals, no roll or pitch; yaw None writes
    "0", a number is written with 6 decimals."""
    return f"{x:.3f} {y:.3f} {z:.3f} 0 0 " + ("0" if yaw is None else f"{yaw:.6f}")


def box_geometry(sx, sy, sz, digits=3):
    return f"<box><size>{sx:.{digits}f} {sy:.{digits}f} {sz:.{digits}f}</size></box>"


def collision_and_visual(name, pose_text, geometry):
    """A collision and its identical visual, one line each (indented for a link in a model in a
    world); geometry is what goes inside <geometry>."""
    inner = f"<pose>{pose_text}</pose><geometry>{geometry}</geometry>"
    return [f'        <collision name="{name}">{inner}</collision>',
            f'        <visual name="{name}">{inner}</visual>']


def box(name, x, y, z, sx, sy, sz, yaw=None, size_digits=3):
    """A box centred at (x, y, z), sx by sy by sz, as a collision and its visual (two lines)."""
    return collision_and_visual(name, pose(x, y, z, yaw), box_geometry(sx, sy, sz, size_digits))


def include(model, name, x, y, yaw):
    """<include> of model://<model> named `name` on the ground at (x, y); yaw is text."""
    return ["    <include>",
            f"      <uri>model://{model}</uri>",
            f"      <name>{name}</name>",
            f"      <pose>{num(x)} {num(y)} 0 0 0 {yaw}</pose>",
            "    </include>"]


def world_open(name):
    return ['<sdf version="1.9">', f'  <world name="{name}">']


def physics(step):
    """The <physics> line, dart with max step `step` (text)."""
    return f'    <physics type="dart"><max_step_size>{step}</max_step_size></physics>'


def static_model_open(model, link):
    """Opens a static model and its first link (close with '      </link>', '    </model>')."""
    return [f'    <model name="{model}">', "      <static>true</static>", f'      <link name="{link}">']


# ---- geometry -----------------------------------------------------------------------------

def corners(cx, cy, yaw, length, width):
    c, s = math.cos(yaw), math.sin(yaw)
    return [(cx + c * u - s * v, cy + s * u + c * v)
            for u, v in ((length / 2, width / 2), (-length / 2, width / 2),
                         (-length / 2, -width / 2), (length / 2, -width / 2))]


def boxes_overlap(a, b):
    """Separating-axis test of two convex quadrilaterals (lists of 4 corners)."""
    for poly in (a, b):
        for i in range(4):
            (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % 4]
            nx, ny = y0 - y1, x1 - x0
            pa = [nx * x + ny * y for x, y in a]
            pb = [nx * x + ny * y for x, y in b]
            if max(pa) <= min(pb) or max(pb) <= min(pa):
                return False
    return True


# ---- command line -------------------------------------------------------------------------

class UsageError(Exception):
    pass


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit status 2 (argparse's own prints the usage too)
        raise UsageError(message)


def finite(text):
    """argparse type: a finite float."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}")
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return v


def parse_pose(text):
    """argparse type: "X,Y,YAW" or "X,Y" (yaw 0) -> (x, y, yaw)."""
    parts = text.split(",")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = []
    if len(values) not in (2, 3) or not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError(f"expected X,Y,YAW (numbers), got {text!r}")
    return tuple(values) if len(values) == 3 else (values[0], values[1], 0.0)


def join_negative_values(argv, value_options):
    """`--start -7,2.5,0` -> `--start=-7,2.5,0` (argparse takes "-7,..." for an option), for the
    options in value_options."""
    out, i = [], 0
    while i < len(argv):
        if argv[i] in value_options and i + 1 < len(argv) and re.match(r"-[\d.]", argv[i + 1]):
            out.append(f"{argv[i]}={argv[i + 1]}")
            i += 2
        else:
            out.append(argv[i])
            i += 1
    return out


def check_int_range(option, v, lo, hi):
    """--option must be a whole number in lo..hi."""
    if not lo <= v <= hi:
        raise UsageError(f"--{option} must be in {lo}..{hi}, got {v}")


def check_range(option, v, lo, hi, unit, why=""):
    """--option must be in [lo, hi] `unit`; why, if given, follows the unit (" (because ...)")."""
    if not lo <= v <= hi:
        raise UsageError(f"--{option} must be in [{lo:g}, {hi:g}] {unit}{why}, got {v:g}")


def fail(prog, message):
    """Prints "<prog>: error: <message>" on stderr; returns the exit status, 2."""
    print(f"{prog}: error: {message}", file=sys.stderr)
    return 2


def write_file(path, text):
    with open(path, "w") as f:
        f.write(text)


def write_output(prog, path, text, summary, what="--out: "):
    """Writes text to path ("-": standard output) and, for a file, prints "<path>: <summary>".
    Returns the exit status: 0, or 2 after one line on stderr if the file cannot be written."""
    if path == "-":
        sys.stdout.write(text)
        return 0
    try:
        write_file(path, text)
    except OSError as e:
        return fail(prog, f"{what}cannot write {path}: {e.strerror}")
    print(f"{path}: {summary}")
    return 0
