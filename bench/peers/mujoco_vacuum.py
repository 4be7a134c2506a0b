"""The peers' job in MuJoCo: Aula's `aula run vacuum --headless --algorithm=bounce --seed=S`, built
from Aula's own world and settings, stepped for the run's sim time, its coverage counted as Aula's
referee counts it. Prints one JSON line: MuJoCo's version, the coverage, and the timings of the
model's building and of the stepping alone.

  mujoco_vacuum.py SETTINGS [SEED]    SETTINGS: the output of `aula config vacuum`

What it models, as Aula does (libs/physics, drivers/):
  - the house: every static box and cylinder of the world, at its pose;
  - the roomba: its collision cylinder on a planar joint (x, y, yaw: slide, slide, hinge), driven
    by velocity servos with Aula's force limits (mass x 10 m/s^2, the cylinder's Izz x 30 rad/s^2),
    the body-frame command turned into world-frame rates every physics step;
  - contact friction 0.3; the bumper pressed while the robot has a contact (within 1 mm);
  - the laser's beams cast by mj_multiRay from its mount, at its rate, clamped to its range;
  - pose samples at the pose3d plugin's rate, the controller every Vacuum.Period.
What differs: MuJoCo's soft contacts (its default solref/solimp) against DART's hard LCP contacts
with Bullet's collision detection; a velocity actuator (kv = inertia / step, Euler) against DART's servo
constraint; the laser cast on MuJoCo's geoms against Aula's 2D ray caster of the same shapes; all
in one process with no bus, where Aula runs a simulator, a component and a referee in lockstep.
"""
import json
import math
import sys
import time
from dataclasses import dataclass

import mujoco
import numpy as np

from aula_world import fail, read_settings, read_world, setting
from bounce import Bounce
from coverage import coverage

MAX_LINEAR_ACCEL = 10.0  # m/s^2: Aula's servo limit (libs/physics/src/physics_world.cpp)
MAX_ANGULAR_ACCEL = 30.0  # rad/s^2
FRICTION = 0.3
# The bumper reads contacts closer than this; an equal gap keeps them from pushing until they touch.
# Without it MuJoCo's soft contacts flicker on and off while the robot presses a wall (1-2 steps each).
BUMPER_MARGIN_M = 0.001


@dataclass
class Job:
    """The run's numbers, from the settings and the world's plugins."""
    step_s: float
    period_s: float
    duration_s: float
    max_v_mps: float
    max_w_radps: float
    pose_rate_hz: float
    laser_rate_hz: float
    seed: int


def quat_of(pose):
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, pose[:3, :3].flatten())
    return quat


def fmt(values):
    return " ".join(repr(float(v)) for v in values)


def static_geom(p):
    where = f'name="{p.name}" pos="{fmt(p.pose[:3, 3])}" quat="{fmt(quat_of(p.pose))}"'
    if p.kind == "box":
        return f'<geom {where} type="box" size="{fmt(np.array(p.size_m) / 2)}"/>'
    return f'<geom {where} type="cylinder" size="{p.radius_m!r} {p.length_m / 2!r}"/>'


def robot_body(robot):
    b = robot.body
    izz = robot.mass_kg * b.radius_m ** 2 / 2  # DART's CylinderShape inertia, as Aula sets it
    ixx = robot.mass_kg * (3 * b.radius_m ** 2 + b.length_m ** 2) / 12
    return f'''<body name="robot">
      <joint name="x" type="slide" axis="1 0 0"/><joint name="y" type="slide" axis="0 1 0"/>
      <joint name="yaw" type="hinge" axis="0 0 1"/>
      <inertial pos="{fmt(b.pose[:3, 3])}" mass="{robot.mass_kg!r}" diaginertia="{ixx!r} {ixx!r} {izz!r}"/>
      <geom name="robot" type="cylinder" size="{b.radius_m!r} {b.length_m / 2!r}" pos="{fmt(b.pose[:3, 3])}"
            margin="{BUMPER_MARGIN_M}" gap="{BUMPER_MARGIN_M}"/>
    </body>''', izz


def servos(robot, izz, step_s):
    force_n = robot.mass_kg * MAX_LINEAR_ACCEL
    torque_nm = max(1e-3, izz * MAX_ANGULAR_ACCEL)
    rows = []
    joints = (("x", robot.mass_kg, force_n), ("y", robot.mass_kg, force_n), ("yaw", izz, torque_nm))
    for joint, inertia, limit in joints:
        # kv = inertia / step: an explicit (Euler) step closes the velocity gap at once within the force
        # limit, as DART's servo does (a stiffer kv overshoots by a clamped force's step and chatters).
        kv = inertia / step_s
        rows.append(f'<velocity joint="{joint}" kv="{kv!r}" forcerange="{-limit!r} {limit!r}"/>')
    return "\n    ".join(rows)


def mjcf(world, step_s):
    body, izz = robot_body(world.robot)
    statics = "\n    ".join(static_geom(p) for p in world.statics)
    return f'''<mujoco model="aula-vacuum">
  <option timestep="{step_s!r}" integrator="Euler"/>
  <default><geom friction="{FRICTION} 0.005 0.0001"/></default>
  <worldbody>
    {statics}
    {body}
  </worldbody>
  <actuator>
    {servos(world.robot, izz, step_s)}
  </actuator>
</mujoco>'''


class Laser:
    """The laser plugin's beams from its mount on the robot, cast on every geom but the robot's."""

    def __init__(self, model, robot):
        p = robot.plugins["laser"]
        self.samples = int(p["samples"])
        min_angle, max_angle = float(p["min_angle"]), float(p["max_angle"])
        beam_rad = min_angle + np.arange(self.samples) * ((max_angle - min_angle) / (self.samples - 1))
        self.min_range_m, self.max_range_m = float(p["min_range"]), float(p["max_range"])
        mount = [float(v) for v in p.get("pose", "0 0 0 0 0 0").split()]
        self.mount_m = np.array(mount[:3])
        self.height_m = robot.start_pose[2, 3] + mount[2]  # the robot stays on its plane
        # Each beam's direction in the robot's frame (the mount's yaw included), turned by the robot's yaw per scan.
        self.beams = np.column_stack((np.cos(beam_rad + mount[5]), np.sin(beam_rad + mount[5])))
        self.directions = np.zeros((self.samples, 3))
        self.body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "robot")
        self.geom_ids = np.zeros(self.samples, dtype=np.int32)
        self.ranges_m = np.zeros(self.samples)
        self.cpu_s = 0.0  # spent in scan(): the laser's share of the stepping

    def scan(self, model, data, x_m, y_m, yaw_rad):
        """The ranges (m) of one scan, as Aula's: no echo within max_range reads max_range."""
        started_s = time.process_time()
        c, s = math.cos(yaw_rad), math.sin(yaw_rad)
        origin = np.array([x_m + c * self.mount_m[0] - s * self.mount_m[1],
                           y_m + s * self.mount_m[0] + c * self.mount_m[1], self.height_m])
        self.directions[:, :2] = self.beams @ np.array([[c, s], [-s, c]])
        mujoco.mj_multiRay(model, data, origin, self.directions.ravel(), None, 1, self.body, self.geom_ids,
                           self.ranges_m, None, self.samples, self.max_range_m)
        np.copyto(self.ranges_m, self.max_range_m, where=self.ranges_m < 0)
        np.clip(self.ranges_m, self.min_range_m, self.max_range_m, out=self.ranges_m)
        self.cpu_s += time.process_time() - started_s
        return self.ranges_m


def steps_per(period_s, step_s):
    return max(1, round(period_s / step_s))


def simulate(model, data, job, laser):
    """The run: (pose samples [(x, y)], bumps) after job.duration_s of sim time."""
    controller = Bounce(job.seed)
    pose_every, laser_every = steps_per(1 / job.pose_rate_hz, job.step_s), steps_per(1 / job.laser_rate_hz, job.step_s)
    control_every = steps_per(job.period_s, job.step_s)
    v_mps = w_radps = 0.0
    poses, bumps, was_pressed = [], 0, False
    for n in range(round(job.duration_s / job.step_s) + 1):
        x_m, y_m, yaw_rad = data.qpos.tolist()
        if n % pose_every == 0:
            poses.append((x_m, y_m))
        if n % laser_every == 0:
            laser.scan(model, data, x_m, y_m, yaw_rad)  # bounce reads no laser; Aula scans all the same
        pressed = data.ncon > 0
        bumps += pressed and not was_pressed
        was_pressed = pressed
        if n > 0 and n % control_every == 0:
            v_mps, w_radps = controller.execute(job.period_s, math.atan2(math.sin(yaw_rad), math.cos(yaw_rad)), pressed)
            v_mps = min(max(v_mps, -job.max_v_mps), job.max_v_mps)
            w_radps = min(max(w_radps, -job.max_w_radps), job.max_w_radps)
        data.ctrl[:] = (v_mps * math.cos(yaw_rad), v_mps * math.sin(yaw_rad), w_radps)
        mujoco.mj_step(model, data)
    return poses, bumps


def job_of(values, world, seed):
    r = world.robot
    return Job(step_s=setting(values, "Simulator.PhysicsStep"), period_s=setting(values, "Vacuum.Period"),
               duration_s=setting(values, "Vacuum.Referee.Duration"),
               max_v_mps=min(setting(values, "Vacuum.MaxV"), r.plugin("motors", "max_v")),
               max_w_radps=min(setting(values, "Vacuum.MaxW"), r.plugin("motors", "max_w")),
               pose_rate_hz=r.plugin("pose3d", "rate_hz"), laser_rate_hz=r.plugin("laser", "rate_hz"), seed=seed)


def clocks():
    return time.perf_counter(), time.process_time()


def main(argv):
    if len(argv) not in (2, 3):
        fail("usage: " + __doc__.split("\n\n")[1].strip())
    start = clocks()
    values, world_path = read_settings(argv[1])
    world = read_world(world_path)
    job = job_of(values, world, int(argv[2]) if len(argv) == 3 else 1)
    model = mujoco.MjModel.from_xml_string(mjcf(world, job.step_s))
    data = mujoco.MjData(model)
    data.qpos[:] = (world.robot.start_pose[0, 3], world.robot.start_pose[1, 3],
                    math.atan2(world.robot.start_pose[1, 0], world.robot.start_pose[0, 0]))
    mujoco.mj_forward(model, data)
    built = clocks()
    laser = Laser(model, world.robot)
    poses, bumps = simulate(model, data, job, laser)
    stepped = clocks()
    covered, floor_m2 = coverage(world.statics, world.robot.start_pose[:2, 3], poses,
                                 setting(values, "Vacuum.Map.Resolution"), setting(values, "Vacuum.Map.ZBand"),
                                 setting(values, "Vacuum.Referee.RobotRadius"))
    counted = clocks()
    print(json.dumps({
        "mujoco": mujoco.__version__, "coverage_percent": round(covered, 6), "floor_area_m2": round(floor_m2, 4),
        "bumps": bumps, "pose_samples": len(poses), "sim_time_s": job.duration_s,
        "build_wall_s": built[0] - start[0], "build_cpu_s": built[1] - start[1],
        "step_wall_s": stepped[0] - built[0], "step_cpu_s": stepped[1] - built[1],
        "laser_cpu_s": laser.cpu_s, "coverage_wall_s": counted[0] - stepped[0]}))


if __name__ == "__main__":
    main(sys.argv)
