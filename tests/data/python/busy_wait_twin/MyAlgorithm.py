# Paced by waiting on time.perf_counter() (a wall-clock habit: RoboticsAcademy runs in real time);
# sleep_twin is the same program with time.sleep. On Aula both are sim time: the same run.
import time

import HAL

turns = 0
while True:
    start = time.perf_counter()
    front = min(HAL.getLaserData().values[70:110])
    HAL.setV(0.3 if front > 0.4 else 0.0)
    HAL.setW(0.0 if front > 0.4 else 0.9)
    turns += front <= 0.4
    while time.perf_counter() - start < 0.25:
        pass
