# The Python port of tests/data/plugins/vacuum_bounce.cpp, line by line: the same report for
# the same seed proves that the two languages see one API.
import math


def wrap(a):
    while a > math.pi:
        a -= 2 * math.pi
    while a < -math.pi:
        a += 2 * math.pi
    return a


def beam_at(scan, angle_rad):
    """The range of the first beam at or past angle_rad, in metres."""
    for i in range(scan.numLaser):
        if scan.angle(i) >= angle_rad:
            return float(scan.values_m[i])
    return 0.0


class MyAlgorithm:
    def __init__(self, seed):
        self.t = 0.0
        self.phase_start = 0.0
        self.target = 0.0
        self.phase = 0
        self.turns = 0

    def execute(self, api):
        self.t += api.period_s
        yaw = api.pose3d.getYaw()
        scan = api.laser.getLaserData()
        front_mm = 100000
        for i in range(80, min(100, len(scan.distanceData))):
            front_mm = min(front_mm, int(scan.distanceData[i]))
        if self.phase == 0 and (api.bumper.getBumperData().state == 1 or front_mm < 350):
            self.phase = 1
            self.phase_start = self.t
            self.turns += 1
        v, w = 0.5, 0.0
        if self.phase == 1:  # back off
            v = -0.15
            if self.t - self.phase_start > 0.35:
                self.phase = 2
                self.phase_start = self.t
                # Towards the freer side (the beams at +-60 degrees), further at every 4th bounce.
                left_m, right_m = beam_at(scan, math.pi / 3), beam_at(scan, -math.pi / 3)
                side = 1.0 if left_m > right_m else -1.0
                self.target = wrap(yaw + side * (1.2 + 0.3 * (self.turns % 4)))
        elif self.phase == 2:  # turn
            v = 0.0
            error = wrap(self.target - yaw)
            w = math.copysign(min(2.5, 0.4 + 3.0 * abs(error)), error)
            if abs(error) < 0.08 or self.t - self.phase_start > 4.0:
                self.phase = 0
        api.motors.sendV(v)
        api.motors.sendW(w)
