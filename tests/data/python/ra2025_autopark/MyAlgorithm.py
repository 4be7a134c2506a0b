# RoboticsAcademy 2025's shape: `import HAL`, `import WebGUI`, `import Frequency`, the loop paced
# by Frequency.tick(). Watches the right laser while creeping along the lane; after 8 s of sim
# time (time.time()) it backs up for 2 s and stops.
import time

import Frequency
import HAL
import WebGUI

t0 = time.time()
closest = float("inf")
while True:
    right = HAL.getRightLaserData()
    closest = min(closest, min(right.values))
    elapsed = time.time() - t0
    if elapsed < 8.0:
        HAL.setV(0.8)
    elif elapsed < 10.0:
        HAL.setV(-0.5)
    else:
        HAL.setV(0.0)
    HAL.setW(-0.8 * HAL.getPose3d().yaw)
    if abs(elapsed - 10.0) < 0.02:
        print(f"closest on the right: {closest:.2f} m")
    Frequency.tick(20)
