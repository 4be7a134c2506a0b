# busy_wait_twin's program paced by time.sleep: the same run.
import time

import HAL

turns = 0
while True:
    front = min(HAL.getLaserData().values[70:110])
    HAL.setV(0.3 if front > 0.4 else 0.0)
    HAL.setW(0.0 if front > 0.4 else 0.9)
    turns += front <= 0.4
    time.sleep(0.25)
