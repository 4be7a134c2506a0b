# RoboticsAcademy 2021-23's shape (the web template): `from HAL import HAL`, `from GUI import GUI`,
# a `while True:` body the template ran once a period, with no time.sleep. A bump-and-turn with
# time.time() timers: ahead until the bumper or the laser says a wall, back 1 s, turn 1.5 s.
from GUI import GUI
from HAL import HAL
import time

state, since = "ahead", time.time()
while True:
    now = time.time()
    if state == "ahead":
        HAL.setV(0.3)
        HAL.setW(0.0)
        if HAL.getBumperData().state == 1 or min(HAL.getLaserData().values[60:120]) < 0.25:
            state, since = "back", now
    elif state == "back":
        HAL.setV(-0.15)
        HAL.setW(0.0)
        if now - since > 1.0:
            state, since = "turn", now
    else:
        HAL.setV(0.0)
        HAL.setW(0.8)
        if now - since > 1.5:
            state, since = "ahead", now
            print(f"ahead again at {now:.2f} s")
