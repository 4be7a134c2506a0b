# RoboticsAcademy's data types (common/hal_interfaces: LaserData, Pose3d, BumperData), made from
# Aula's devices, for the exercises' HAL and GUI modules (components/<exercise>/python/HAL.py,
# GUI.py). Conventions are RoboticsAcademy's:
# - LaserData.values: ranges in metres, a list, beam 0 on the right; minAngle/maxAngle are
#   ROS's angles + pi/2, so a 180-degree scan runs from 0 (right) to pi (left); timeStamp in
#   seconds of sim time. A beam with no echo reads inf, as RoboticsAcademy's Gazebo gives it
#   (Aula's own API reads maxRange there): a reading at maxRange is taken as no echo.
# - Pose3d: .x, .y, .z (m), .yaw, .pitch, .roll (rad), .q ([w, x, y, z]), .h, .timeStamp (s).
# - BumperData: .state (1 while touching), .bumper: RIGHT_BUMPER = 0, CENTER_BUMPER = 1,
#   LEFT_BUMPER = 2 (Aula's own API numbers them the other way: 0 left).
import math

import _aula_host as _host

RIGHT_BUMPER = 0
CENTER_BUMPER = 1
LEFT_BUMPER = 2


def _text(title, fields):
    """RoboticsAcademy's print() of its types: `Title: {` and one `   name: value` a line."""
    return title + ": {\n" + "".join(f"   {name}: {value}\n" for name, value in fields) + "}"


class LaserData:
    def __init__(self, values, minAngle, maxAngle, minRange, maxRange, timeStamp):
        self.values = values        # metres, beam 0 on the right
        self.minAngle = minAngle    # rad, angle of the first value (0: right)
        self.maxAngle = maxAngle    # rad, angle of the last value (pi: left)
        self.minRange = minRange    # m
        self.maxRange = maxRange    # m
        self.timeStamp = timeStamp  # s, sim time

    def __str__(self):
        return _text("LaserData", [("minAngle", self.minAngle), ("maxAngle", self.maxAngle), ("minRange", self.minRange),
                                   ("maxRange", self.maxRange), ("timeStamp", self.timeStamp), ("values", self.values)])


def laser_data(scan):
    """RoboticsAcademy's LaserData from Aula's (component.LaserData)."""
    max_range = scan.maxRange
    return LaserData([math.inf if r >= max_range else float(r) for r in scan.values_m], scan.minAngle + math.pi / 2,
                     scan.maxAngle + math.pi / 2, scan.minRange, max_range, scan.timeStamp / 1e6)


class Pose3d:
    def __init__(self, x=0.0, y=0.0, yaw=0.0, timeStamp=0.0):
        self.x = x          # m
        self.y = y          # m
        self.z = 0.0        # m
        self.h = 1
        self.yaw = yaw      # rad, counter-clockwise from +x
        self.pitch = 0.0    # rad
        self.roll = 0.0     # rad
        self.q = [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]  # w, x, y, z
        self.timeStamp = timeStamp  # s, sim time

    def __str__(self):
        return _text("Pose3D", [("x", self.x), ("y", self.y), ("z", self.z), ("H", self.h), ("Yaw", self.yaw),
                                ("Pitch", self.pitch), ("Roll", self.roll), ("quaternion", self.q),
                                ("timeStamp", self.timeStamp)])


def pose3d(pose):
    """RoboticsAcademy's Pose3d from Aula's (component.Pose3d)."""
    return Pose3d(pose.getX(), pose.getY(), pose.getYaw(), pose.utime() / 1e6)


class YawOnlyPose3d:
    """A Pose3d for a robot that is not told where it is (the vacuum): .yaw and .timeStamp; the
    position's attributes say what exists instead."""

    _MISSING = ("x", "y", "z", "q", "q0", "q1", "q2", "q3", "h", "pitch", "roll")

    def __init__(self, yaw, timeStamp, exercise, source="HAL.getPose3d()"):
        self.yaw = yaw
        self.timeStamp = timeStamp
        self._exercise = exercise
        self._source = source  # what the program called: "HAL.getPose3d()", "pose3d.getPose3d()"

    def __getattr__(self, name):
        if name in YawOnlyPose3d._MISSING:
            raise AttributeError(
                f"{self._source}.{name}: the {self._exercise} has no localization in Aula: getPose3d() gives "
                ".yaw (rad) and .timeStamp (s) only; find your way with the laser, the bumper and the yaw")
        raise AttributeError(f"'Pose3d' object has no attribute '{name}'")

    def __str__(self):
        return _text("Pose3D", [("Yaw", self.yaw), ("timeStamp", self.timeStamp)])


class BumperData:
    def __init__(self, state=0, bumper=CENTER_BUMPER, timeStamp=0.0):
        self.state = state      # 1 while touching
        self.bumper = bumper    # RIGHT_BUMPER 0, CENTER_BUMPER 1, LEFT_BUMPER 2
        self.timeStamp = timeStamp

    def __str__(self):
        return _text("Bumper", [("state", self.state), ("bumper", self.bumper)])


def bumper_data(data):
    """RoboticsAcademy's BumperData from Aula's (Aula: 0 left, 2 right; RoboticsAcademy: 0 right)."""
    return BumperData(data.state, 2 - data.bumper, data.timeStamp / 1e6)


# Linear speed, m/s (clamped to the exercise's MaxV): every exercise's HAL.setV.
def setV(v):
    api("HAL.setV()").motors.sendV(float(v))


# Angular speed, rad/s, counter-clockwise (clamped to the exercise's MaxW): every exercise's HAL.setW.
def setW(w):
    api("HAL.setW()").motors.sendW(float(w))


def api(what):
    """The exercise's API of the call now running (`what`: the HAL or GUI function asking)."""
    return _host.current_api(what)


def read(sensor):
    """A HAL sensor read (pacing: a second read of one sensor in a period waits for the next)."""
    _host.sensor_read(sensor)


def missing(module, name, offered):
    """A module's __getattr__ for what RoboticsAcademy has and Aula's world does not."""
    raise AttributeError(f"{module}.{name}: not in Aula's {module} for this exercise; it has {offered}")


def wait_until(ready):
    """Waits period by period until ready() holds (RoboticsAcademy's HAL waits for a first scan)."""
    runner = _host._runner
    while not ready() and runner is not None and runner.is_program and runner.program is not None and not runner.forked():
        import greenlet
        if greenlet.getcurrent() is not runner.program:
            return
        runner.wait_period()
