"""The MuJoCo model's laser and coverage count against Aula's, on a run Aula recorded: every laser
message against mj_multiRay's scan from the pose Aula published at the same sim time (the largest
difference of a beam, after float32 rounding, as Aula sends them), and coverage.py's count of the
recorded poses (to set beside the report's coverage_percent).

  compare_with_aula.py SETTINGS RUN.lcmlog
SETTINGS: the output of `aula config vacuum`; RUN.lcmlog: `aula run vacuum --headless --record=RUN.lcmlog`.
Reads the log with the `lcm` package from PyPI (bench/peers/run.sh installs it)."""
import struct
import sys

import lcm
import mujoco
import numpy as np

from aula_world import fail, read_settings, read_world, setting
from coverage import coverage
from mujoco_vacuum import Laser, mjcf

FINGERPRINT_BYTES = 8  # every LCM message starts with its type's hash


def recorded(log_path, world):
    """{utime: (x, y, yaw)} of the robot's pose3d_t and {utime: ranges} of its laser_t messages."""
    pose_channel, laser_channel = world.robot.plugins["pose3d"]["channel"], world.robot.plugins["laser"]["channel"]
    poses, scans = {}, {}
    for event in lcm.EventLog(log_path, "r"):
        body = event.data[FINGERPRINT_BYTES:]
        if event.channel == pose_channel:
            utime, x_m, y_m, _, yaw_rad = struct.unpack(">qdddd", body[:40])
            poses[utime] = (x_m, y_m, yaw_rad)
        elif event.channel == laser_channel:
            utime, count = struct.unpack(">qi", body[:12])
            scans[utime] = np.array(struct.unpack(f">{count}f", body[12:12 + 4 * count]), dtype=np.float32)
    return poses, scans


def compare_scans(world, poses, scans):
    """(scans compared, the largest beam difference in m, how many scans differ)."""
    model = mujoco.MjModel.from_xml_string(mjcf(world, 0.01))
    data = mujoco.MjData(model)
    laser = Laser(model, world.robot)
    worst_m = []
    for utime in sorted(set(poses) & set(scans)):
        data.qpos[:] = poses[utime]  # the robot's own geom where Aula's was: the rays skip it
        mujoco.mj_forward(model, data)
        worst_m.append(float(np.max(np.abs(laser.scan(model, data, *poses[utime]).astype(np.float32) - scans[utime]))))
    return len(worst_m), max(worst_m, default=0.0), sum(w > 0 for w in worst_m)


def main(argv):
    if len(argv) != 3:
        fail("usage: " + __doc__.split("\n\n")[1].strip())
    values, world_path = read_settings(argv[1])
    world = read_world(world_path)
    poses, scans = recorded(argv[2], world)
    compared, worst_m, differing = compare_scans(world, poses, scans)
    print(f"laser: {compared} scans compared; largest beam difference {worst_m:.6g} m; {differing} scans differ")
    duration_us = round(setting(values, "Vacuum.Referee.Duration") * 1e6)
    graded = [poses[utime][:2] for utime in sorted(poses) if 0 <= utime <= duration_us]
    covered, floor_m2 = coverage(world.statics, world.robot.start_pose[:2, 3], graded,
                                 setting(values, "Vacuum.Map.Resolution"), setting(values, "Vacuum.Map.ZBand"),
                                 setting(values, "Vacuum.Referee.RobotRadius"))
    print(f"coverage of the {len(graded)} recorded poses: {covered:.6f} % of {floor_m2:.4f} m2 "
          "(the report's coverage_percent)")


if __name__ == "__main__":
    main(sys.argv)
