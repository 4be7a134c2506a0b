# RoboticsAcademy 2025's Global Navigation shape: `import HAL`, `import WebGUI`, `import
# Frequency`; WebGUI.getMap, getTargetPose, rowColumn, showNumpy (a picture of the distance to the
# target), and a loop paced by Frequency.tick(). It heads straight for the target, slowing near
# buildings (the map's cells ahead), and stops within 3 m.
import math

import Frequency
import HAL
import numpy as np
import WebGUI

city = WebGUI.getMap('/resources/exercises/global_navigation/images/cityLargenBin.png')
target = WebGUI.getTargetPose()
column, row = WebGUI.rowColumn(target)
rows, columns = np.indices(city.shape)
distance = np.hypot(rows - row, columns - column)
WebGUI.showNumpy((255 * distance / distance.max()).astype(np.uint8))
print(f"target {target[0]:.1f}, {target[1]:.1f} m: cell {column}, {row} of a {city.shape[1]} x {city.shape[0]} map")

while True:
    pose = HAL.getPose3d()
    dx, dy = target[0] - pose.x, target[1] - pose.y
    error = math.atan2(dy, dx) - pose.yaw
    error = math.atan2(math.sin(error), math.cos(error))
    ahead = WebGUI.rowColumn([pose.x + 6 * math.cos(pose.yaw), pose.y + 6 * math.sin(pose.yaw)])
    blocked = city[min(ahead[1], city.shape[0] - 1), min(ahead[0], city.shape[1] - 1)] < 128
    if math.hypot(dx, dy) < 3.0:
        HAL.setV(0.0)
    else:
        HAL.setV(0.5 if blocked or abs(error) > 0.4 else 3.0)
    HAL.setW(max(-1.0, min(1.0, 1.5 * error)))
    Frequency.tick()
