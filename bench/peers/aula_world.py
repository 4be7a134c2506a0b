"""Aula's vacuum job as plain values, read from Aula's own files: the SDF world (its static boxes
and cylinders, and the roomba it includes from worlds/models) and the effective settings
`aula config vacuum` prints. Only what the MuJoCo model and the coverage count need."""
import math
import os
import re
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import numpy as np


def fail(message):
    """A usage or input error: said on stderr, exit code 2 (as Aula's programs do)."""
    print(message, file=sys.stderr)
    sys.exit(2)


@dataclass
class Primitive:
    """A static box (size_m: full x, y, z) or cylinder (radius_m, length_m) at a world pose."""
    name: str
    kind: str
    pose: np.ndarray  # 4x4, world frame
    size_m: tuple = (0.0, 0.0, 0.0)
    radius_m: float = 0.0
    length_m: float = 0.0

    def z_range_m(self):
        r = self.pose[:3, :3]
        half = np.array(self.size_m) / 2 if self.kind == "box" else np.array([self.radius_m] * 2 + [self.length_m / 2])
        reach = np.abs(r) @ half
        return self.pose[2, 3] - reach[2], self.pose[2, 3] + reach[2]

    def yaw_rad(self):
        return math.atan2(self.pose[1, 0], self.pose[0, 0])


@dataclass
class Robot:
    """The one robot of the world: a disc, its start and its devices' parameters (strings)."""
    name: str
    start_pose: np.ndarray  # 4x4
    body: Primitive  # its collision shape, pose relative to the body frame
    mass_kg: float
    plugins: dict = field(default_factory=dict)  # plugin name -> {key: text}

    def plugin(self, name, key):
        try:
            return float(self.plugins[name][key])
        except KeyError:
            fail(f"{self.name}: plugin '{name}' has no <{key}>")


@dataclass
class World:
    path: str
    statics: list
    robot: Robot


def pose_matrix(text):
    """An SDF <pose> (x y z roll pitch yaw) as a 4x4 transform."""
    x, y, z, roll, pitch, yaw = (float(v) for v in (text or "0 0 0 0 0 0").split())
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    m = np.eye(4)
    m[:3, :3] = [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                 [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                 [-sp, cp * sr, cp * cr]]
    m[:3, 3] = (x, y, z)
    return m


def child_pose(element):
    node = element.find("pose")
    return pose_matrix(node.text if node is not None else None)


def read_geometry(collision, pose, where):
    geometry = collision.find("geometry")
    name = collision.get("name", "")
    box, cylinder = geometry.find("box"), geometry.find("cylinder")
    if box is not None:
        return Primitive(name, "box", pose, size_m=tuple(float(v) for v in box.findtext("size").split()))
    if cylinder is not None:
        return Primitive(name, "cylinder", pose, radius_m=float(cylinder.findtext("radius")),
                         length_m=float(cylinder.findtext("length")))
    fail(f"{where}: collision '{name}': only boxes and cylinders are modelled in MuJoCo here")


def model_file(uri, world_path):
    """model://NAME: the models folder beside the world (worlds/models/NAME/model.sdf)."""
    name = uri[len("model://"):]
    path = os.path.join(os.path.dirname(world_path), "models", name, "model.sdf")
    if not os.path.exists(path):
        fail(f"{world_path}: {uri}: no {path}")
    return path


def read_plugins(model):
    plugins = {}
    for plugin in model.findall("plugin"):
        plugins[plugin.get("name")] = {child.tag: (child.text or "").strip() for child in plugin}
    return plugins


def read_robot(model, pose, path):
    link = model.find("link")
    collision = link.find("collision")
    body = read_geometry(collision, child_pose(link) @ child_pose(collision), path)
    mass = float(link.findtext("inertial/mass", "1"))
    return Robot(model.get("name"), pose, body, mass, read_plugins(model))


def read_model(model, pose, path, statics, robots):
    pose = pose @ child_pose(model)
    if model.findtext("static", "false").strip() != "true":
        robots.append(read_robot(model, pose, path))
        return
    for link in model.findall("link"):
        link_pose = pose @ child_pose(link)
        for collision in link.findall("collision"):
            statics.append(read_geometry(collision, link_pose @ child_pose(collision), path))


def parse_xml(path):
    try:
        return ET.parse(path).getroot()
    except (ET.ParseError, OSError) as error:
        fail(f"{path}: {error}")


def read_world(path):
    world = parse_xml(path).find("world")
    if world is None:
        fail(f"{path}: no <world>")
    statics, robots = [], []
    for model in world.findall("model"):
        read_model(model, np.eye(4), path, statics, robots)
    for include in world.findall("include"):
        included = parse_xml(model_file(include.findtext("uri").strip(), path)).find("model")
        if include.findtext("name"):
            included.set("name", include.findtext("name").strip())
        # The include's <pose> stands for the model's own (read_model applies the model's pose after this one).
        read_model(included, child_pose(include) @ np.linalg.inv(child_pose(included)), path, statics, robots)
    if len(robots) != 1:
        fail(f"{path}: {len(robots)} robots; this model of the vacuum job needs exactly one")
    return World(path, statics, robots[0])


def read_settings(path):
    """`aula config vacuum` output: {key: value text without its unit} and the world's path."""
    values, world = {}, None
    with open(path) as lines:
        for line in lines:
            m = re.match(r"\s+([A-Z][\w.]*) = (.*?)    \[", line)
            if m:
                values.setdefault(m.group(1), m.group(2).strip())
            elif line.startswith("world: "):
                world = line[len("world: "):].strip()
    if world is None:
        fail(f"{path}: no 'world:' line (is it the output of `aula config vacuum`?)")
    return values, world


def setting(values, key):
    """A number (or a list of numbers) of the settings, its unit dropped."""
    if key not in values:
        fail(f"settings: no {key} (is it the output of `aula config vacuum`?)")
    numbers = [float(v.split()[0]) for v in values[key].split(",")]
    return numbers[0] if len(numbers) == 1 else numbers
