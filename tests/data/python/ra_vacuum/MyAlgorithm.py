# A vacuum cleaner written to RoboticsAcademy's page (vacuum_cleaner_newmanager, ROS 2), as a
# student of today's course writes it: import HAL and GUI, top-level code, `while True:`,
# time.time() timers and time.sleep(). It runs unchanged on Aula (tests/integration/
# test_python_algorithms.cpp): an outward spiral, then bump-and-turn with random turns; after a bump
# it turns away from the nearer side and says which side touched (RoboticsAcademy's bumper:
# 0 = right).
import GUI
import HAL
import time
import math
import random
from datetime import datetime

SPIRAL_S = 40.0       # seconds of spiral at the start
BACK_S = 0.6          # reverse this long after a bump
TURN_MIN_S, TURN_MAX_S = 0.8, 2.4

print("started at", datetime.now().strftime("%H:%M:%S"))
start = time.time()
state = "spiral"
t0 = time.time()
turn_s = 0.0
direction = 1.0

while True:
    laser = HAL.getLaserData()
    bumper = HAL.getBumperData()
    front = min(laser.values[70:110])   # beams ahead (beam 0 on the right, 90 straight ahead)

    if state in ("spiral", "forward") and (bumper.state == 1 or front < 0.25):
        # Turn away from the nearer side (beam 0 on the right).
        direction = 1.0 if sum(laser.values[:60]) < sum(laser.values[120:]) else -1.0
        side = "left" if bumper.bumper == HAL.LEFT_BUMPER else "right" if bumper.bumper == HAL.RIGHT_BUMPER else "centre"
        what = f"bump on the {side}" if bumper.state == 1 else f"wall {front:.2f} m ahead"
        print(f"{time.time() - start:7.2f} s: {what}, backing off, then turning {'left' if direction > 0 else 'right'}")
        state, t0 = "back", time.time()

    if state == "spiral":
        elapsed = time.time() - t0
        HAL.setV(0.3)
        HAL.setW(max(0.25, 1.6 / (1.0 + 0.25 * elapsed)))
        if elapsed > SPIRAL_S:
            state = "forward"
    elif state == "back":
        HAL.setV(-0.15)
        HAL.setW(0.0)
        if time.time() - t0 > BACK_S:
            state, t0 = "turn", time.time()
            turn_s = random.uniform(TURN_MIN_S, TURN_MAX_S)
    elif state == "turn":
        HAL.setV(0.0)
        HAL.setW(0.9 * direction)
        if time.time() - t0 > turn_s:
            state = "forward"
    else:
        HAL.setV(0.3)
        HAL.setW(0.0)

    time.sleep(0.03)
