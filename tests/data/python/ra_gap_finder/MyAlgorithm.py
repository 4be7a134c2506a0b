# An Autopark gap finder in RoboticsAcademy's shape (autoparking_newmanager): `import HAL`,
# `while True:`, time.time(). Along the lane, the right laser's beams around straight out read inf
# (no echo: nothing within range, the gap between two parked cars); once they have read inf over
# 2 m of travel, a fixed manoeuvre timed on the clock: on for a fixed time, a stop, then two
# reversing arcs of 3 m radius into the gap. The numbers are RA's street's (the cars 4.9 m long at
# y = -3, the free gap 8.6 m, the car starting at y = 2.5); it reads no map and no curb.
# Written for Aula's tests (tests/integration/test_python_algorithms.cpp), not a student's.
import GUI
import HAL
import time
import math

SPEED = 1.0          # m/s, along the lane and in the arcs
RADIUS = 3.0         # m, the two reversing arcs
ARC_ANGLE = 1.420    # rad: two arcs of 3 m moving the car 5.1 m towards the curb (2.5 -> -2.6)
GAP_TRAVEL = 2.0     # m of travel with the beams out to the right reading inf
ON_PAST_GAP = 7.93   # s at SPEED once the gap is confirmed: the arcs' start, 12.9 m along
CONE = 10            # beams either side of the middle one (about 10 degrees)


def right_is_free(laser):
    middle = len(laser.values) // 2
    return all(math.isinf(r) for r in laser.values[middle - CONE:middle + CONE + 1])


state = "search"
gap_from = None
t0 = time.time()
while True:
    pose = HAL.getPose3d()
    right = HAL.getRightLaserData()
    v = w = 0.0
    if state == "search":
        v = SPEED
        if right_is_free(right):
            if gap_from is None:
                gap_from = pose.x
            elif pose.x - gap_from >= GAP_TRAVEL:
                print(f"gap: inf from x = {gap_from:.2f} to {pose.x:.2f} m")
                state, t0 = "on", time.time()
        else:
            gap_from = None
    elif state == "on":
        v = SPEED
        if time.time() - t0 >= ON_PAST_GAP:
            state, t0 = "stop", time.time()
    elif state == "stop":
        if time.time() - t0 >= 1.0:
            print(f"reversing from x = {pose.x:.2f} m")
            state, t0 = "arc in", time.time()
    elif state == "arc in":      # reversing, the rear swinging right
        v, w = -SPEED, SPEED / RADIUS
        if time.time() - t0 >= ARC_ANGLE * RADIUS / SPEED:
            state, t0 = "arc out", time.time()
    elif state == "arc out":     # reversing, straightening up
        v, w = -SPEED, -SPEED / RADIUS
        if time.time() - t0 >= ARC_ANGLE * RADIUS / SPEED:
            state = "parked"
            print(f"parked at ({pose.x:.2f}, {pose.y:.2f}), yaw {math.degrees(pose.yaw):.1f} deg")
    HAL.setV(v)
    HAL.setW(w)
    time.sleep(0.02)
