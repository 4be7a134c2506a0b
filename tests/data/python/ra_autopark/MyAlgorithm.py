# An Autopark state machine written to RoboticsAcademy's page (autoparking_newmanager, ROS 2):
# import HAL and GUI, top-level code, `while True:`, time.time() and time.sleep(). It runs
# unchanged on Aula (tests/integration/test_python_algorithms.cpp): along the lane until the right
# laser has seen a car, a gap longer than the car and the next car; on past the gap, a pause,
# then two reversing arcs into it, and centred between the front and rear cars.
# The street's numbers are RoboticsAcademy's, as on Aula's Autopark page (the car 4 x 2 m, the right laser
# 0.5 m ahead of the centre, 1.25 m to its right).
import GUI
import HAL
import time
import math

CAR_LENGTH, CAR_WIDTH = 4.0, 2.0
RIGHT_LASER_X, RIGHT_LASER_Y = 0.5, -1.25
RADIUS = 5.0          # m, the reversing arcs
LANE_Y = 0.0          # m, where to drive while searching
CAR_NEAR = 2.6        # m, a parked car beside us
CURB_MARGIN = 0.3     # m


def clamp(value, low, high):
    return max(low, min(value, high))


def middle(laser):
    return laser.values[len(laser.values) // 2]


state = "search"
seen_car = False
gap_start = None
gap_end = goal_y = 0.0
t0 = time.time()

while True:
    pose = HAL.getPose3d()
    right = HAL.getRightLaserData()
    front = HAL.getFrontLaserData()
    back = HAL.getBackLaserData()
    side = middle(right)
    laser_x = pose.x + RIGHT_LASER_X
    v = w = 0.0
    if state == "search":
        v = 1.5
        w = clamp(-0.5 * (pose.y - LANE_Y) - 1.5 * pose.yaw, -0.3, 0.3)
        if side < CAR_NEAR:
            goal_y = pose.y + RIGHT_LASER_Y - side - CAR_WIDTH / 2 + CURB_MARGIN
            if gap_start is not None and laser_x - gap_start > CAR_LENGTH + 1.5:
                gap_end = laser_x
                state = "past the gap"
                print(f"slot found: {gap_start:.2f} .. {gap_end:.2f} m, parking at y = {goal_y:.2f} m")
            seen_car = True
            gap_start = None
        elif seen_car and gap_start is None:
            gap_start = laser_x
    elif state == "past the gap":
        v = 1.0
        w = clamp(-0.5 * (pose.y - LANE_Y) - 1.5 * pose.yaw, -0.3, 0.3)
        if pose.x >= gap_end + 1.6:
            state, t0 = "pause", time.time()
    elif state == "pause":  # a second's stop before reversing, timed on the clock
        if time.time() - t0 > 1.0:
            state = "reverse in"
    elif state == "reverse in":  # the rear swinging right
        v, w = -0.8, 0.8 / RADIUS
        if pose.y - goal_y <= RADIUS * (1 - math.cos(pose.yaw)):
            state = "straighten"
    elif state == "straighten":
        v, w = -0.8, -0.8 / RADIUS
        if pose.yaw <= 0.0:
            state = "centre"
    elif state == "centre":
        error = (middle(front) - middle(back)) / 2
        if abs(error) < 0.1:
            state = "parked"
            print(f"parked at ({pose.x:.2f}, {pose.y:.2f}), yaw {math.degrees(pose.yaw):.1f} deg")
        else:
            v, w = clamp(0.8 * error, -0.5, 0.5), -pose.yaw
    HAL.setV(v)
    HAL.setW(w)
    time.sleep(0.05)
