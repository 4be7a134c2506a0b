# The Python port of tests/data/plugins/autopark_reverse.cpp, line by line: the same report
# proves that the two languages see one API.
import math

RADIUS_M, LANE_Y, CAR_NEAR_M, CURB_MARGIN_M = 5.0, 0.0, 2.6, 0.3


def clamp(value, low, high):
    return max(low, min(value, high))


def side_range(scan):
    return float(scan.values_m[scan.numLaser // 2])


class MyAlgorithm:
    def __init__(self, seed):
        self.phase = 0
        self.seen_car = False
        self.gap_start_x, self.gap_end_x, self.goal_y = -1e10, 0.0, 0.0

    def execute(self, api):
        right = api.laser3.getLaserData()
        if right.numLaser == 0 or api.laser1.getLaserData().numLaser == 0 or api.laser2.getLaserData().numLaser == 0:
            return
        x, y, yaw = api.pose3d.getX(), api.pose3d.getY(), api.pose3d.getYaw()
        side_m, laser_x = side_range(right), x + api.mount3.x_m
        v, w = 0.0, 0.0
        if self.phase == 0:  # along the lane: a car, the gap, the next car
            v = 1.5
            w = clamp(-0.5 * (y - LANE_Y) - 1.5 * yaw, -0.3, 0.3)
            if side_m < CAR_NEAR_M:
                self.goal_y = y + api.mount3.y_m - side_m - api.car_width_m / 2 + CURB_MARGIN_M
                if self.gap_start_x > -1e9 and laser_x - self.gap_start_x > api.car_length_m + 1.5:
                    self.gap_end_x = laser_x
                    self.phase = 1
                    api.status = "slot found"
                self.seen_car = True
                self.gap_start_x = -1e10
            elif self.seen_car and self.gap_start_x < -1e9:
                self.gap_start_x = laser_x
        elif self.phase == 1:  # on until the arcs' start
            v = 1.0
            w = clamp(-0.5 * (y - LANE_Y) - 1.5 * yaw, -0.3, 0.3)
            if x >= self.gap_end_x + 1.6:
                self.phase = 2
        elif self.phase == 2:  # reverse, the rear swinging right
            v = -0.8
            w = 0.8 / RADIUS_M
            if y - self.goal_y <= RADIUS_M * (1 - math.cos(yaw)):
                self.phase = 3
        elif self.phase == 3:  # reverse, straightening
            v = -0.8
            w = -0.8 / RADIUS_M
            if yaw <= 0.0:
                self.phase = 4
        elif self.phase == 4:  # centre between the cars
            error = (side_range(api.laser1.getLaserData()) - side_range(api.laser2.getLaserData())) / 2
            if abs(error) < 0.1:
                self.phase = 5
                api.status = "parked"
            else:
                v = clamp(0.8 * error, -0.5, 0.5)
                w = -yaw
        api.motors.sendV(v)
        api.motors.sendW(w)
