# JdeRobot-Academy's devices (2017-18: the ICE/comm clients its component handed MyAlgorithm), made
# from Aula's, for a class MyAlgorithm(pose3d, motors, laser, bumper) (host.py; each exercise's
# academy_devices.py says which and in what order). A device keeps no data of its own: each call
# reads the exercise's API of the call now running, so the class may keep it from its __init__.
# Conventions are the original's (original-exercises.md, "The original's interfaces"):
# - LaserData: distanceData in int millimetres and values in metres (comm's name), beam 0 on the
#   right, minAngle -pi/2 .. maxAngle +pi/2 (rad), minRange/maxRange (m), numLaser, timeStamp (s);
# - Pose3DData: x, y, z (m), yaw, pitch, roll (rad), h, q and q0..q3 (w, x, y, z), timeStamp (s);
#   the client's getX(), getY(), getYaw() too;
# - BumperData: state 1 while touching, bumper 0 left, 1 centre, 2 right (as Aula's own);
# - Motors: sendV (m/s), sendW / sendAZ (rad/s), sendL, and the original's setters.
import math

import aula_ra as _ra


class LaserData:
    def __init__(self, scan):
        self.distanceData = [int(mm) for mm in scan.distanceData]  # mm, beam 0 on the right
        self.values = [float(m) for m in scan.values_m]             # m, the same beams
        self.numLaser = int(scan.numLaser)
        self.minAngle = scan.minAngle    # rad, the first beam's (-pi/2: right)
        self.maxAngle = scan.maxAngle    # rad, the last beam's (+pi/2: left)
        self.minRange = scan.minRange    # m
        self.maxRange = scan.maxRange    # m
        self.timeStamp = scan.timeStamp / 1e6  # s, sim time

    def __str__(self):
        return _ra._text("LaserData", [("numLaser", self.numLaser), ("minAngle", self.minAngle),
                                       ("maxAngle", self.maxAngle), ("distanceData", self.distanceData)])


class Pose3DData:
    def __init__(self, x, y, yaw, timeStamp):
        self.x, self.y, self.z = x, y, 0.0   # m
        self.h = 1
        self.yaw, self.pitch, self.roll = yaw, 0.0, 0.0  # rad
        self.q0, self.q1, self.q2, self.q3 = math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)
        self.q = [self.q0, self.q1, self.q2, self.q3]
        self.timeStamp = timeStamp  # s

    def __str__(self):
        return _ra._text("Pose3D", [("x", self.x), ("y", self.y), ("z", self.z), ("yaw", self.yaw)])


class _Device:
    """One of the exercise's devices, `attribute` of its API (api.pose3d...), read at each call."""

    def __init__(self, attribute, name):
        self._attribute, self._name = attribute, name

    def _device(self, method):
        return getattr(_ra.api(f"{self._name}.{method}()"), self._attribute)


class Pose3dClient(_Device):
    def __init__(self, attribute="pose3d", name="pose3d"):
        super().__init__(attribute, name)

    def getPose3d(self):
        pose = self._device("getPose3d")
        return Pose3DData(pose.getX(), pose.getY(), pose.getYaw(), pose.utime() / 1e6)

    getPose3D = getPose3d

    def getX(self):
        return self._device("getX").getX()

    def getY(self):
        return self._device("getY").getY()

    def getYaw(self):
        return self._device("getYaw").getYaw()

    def getPitch(self):
        return 0.0

    def getRoll(self):
        return 0.0


class YawOnlyPose3dClient(_Device):
    """The vacuum's pose3d: the yaw only (Aula's vacuum is not told where it is); the position's
    names say what exists instead."""

    def __init__(self, exercise):
        super().__init__("pose3d", "pose3d")
        self._exercise = exercise

    def getPose3d(self):
        api = _ra.api("pose3d.getPose3d()")
        return _ra.YawOnlyPose3d(api.pose3d.getYaw(), api.time_s(), self._exercise, "pose3d.getPose3d()")

    def getYaw(self):
        return self._device("getYaw").getYaw()

    def __getattr__(self, name):
        if name in ("getX", "getY", "getZ"):
            raise AttributeError(f"pose3d.{name}(): the {self._exercise} has no localization in Aula: pose3d gives "
                                 "getYaw() and getPose3d().yaw only; find your way with the laser, the bumper and the yaw")
        raise AttributeError(f"'Pose3dClient' object has no attribute '{name}'")


class LaserClient(_Device):
    def getLaserData(self):
        return LaserData(self._device("getLaserData").getLaserData())

    def hasproxy(self):
        return True


class BumperData:
    def __init__(self, bumper=1, state=0, timeStamp=0.0):
        self.bumper = bumper        # 0 left, 1 centre, 2 right, as the original's
        self.state = state          # 1 while touching
        self.timeStamp = timeStamp  # s

    def __str__(self):
        return _ra._text("BumperData", [("bumper", self.bumper), ("state", self.state)])


class BumperClient(_Device):
    def getBumperData(self):
        data = self._device("getBumperData").getBumperData()
        return BumperData(data.bumper, data.state, data.timeStamp / 1e6)  # a copy, as the original's


class MotorsClient(_Device):
    """Motors: sendV (m/s), sendW and the original's sendAZ (rad/s), clamped to MaxV and MaxW."""

    def __init__(self, attribute="motors", name="motors"):
        super().__init__(attribute, name)

    def sendV(self, v):
        self._device("sendV").sendV(float(v))

    def sendW(self, w):
        self._device("sendW").sendW(float(w))

    sendAZ = sendW

    def sendL(self, l):
        self._device("sendL").sendL(float(l))

    def setV(self, v):
        self.sendV(v)

    def setW(self, w):
        self.sendW(w)

    def getV(self):
        return self._device("getV").getV()

    def getW(self):
        return self._device("getW").getW()

    def getMaxV(self):
        return self._device("getMaxV").maxV()

    def getMaxW(self):
        return self._device("getMaxW").maxW()

    def sendVelocities(self, *unused):
        pass  # the original sent what setV/setW had set; Aula sends every command at once
