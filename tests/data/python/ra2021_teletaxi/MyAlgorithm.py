# RoboticsAcademy 2021-23's Global Navigation shape: `from HAL import HAL`, `from GUI import GUI`,
# `from MAP import MAP`; MAP.getMap(url) and MAP.rowColumn(pose) ([column, row]), GUI.showPath,
# then a `while True:` body with no time.sleep. A breadth-first search over the free cells (walls
# grown by two cells), then a follower that steers at a cell eight steps ahead on the path.
from collections import deque
import math

import cv2
import numpy as np
from GUI import GUI
from HAL import HAL
from MAP import MAP

grid = MAP.getMap('/RoboticsAcademy/exercises/static/exercises/global_navigation/web-template/assets/img/cityLargeBin.png')
free = cv2.erode((grid > 127).astype(np.uint8), np.ones((5, 5), np.uint8)) > 0
target = GUI.getTargetPose()
goal = tuple(MAP.rowColumn(target))
here = HAL.getPose3d()
start = tuple(MAP.rowColumn([here.x, here.y]))
came = {goal: None}
queue = deque([goal])
while queue and start not in came:
    column, row = queue.popleft()
    for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        cell = (column + dc, row + dr)
        if cell not in came and 0 <= cell[1] < free.shape[0] and 0 <= cell[0] < free.shape[1] and \
                (free[cell[1], cell[0]] or cell == start):
            came[cell] = (column, row)
            queue.append(cell)
path = []
cell = start if start in came else None
while cell is not None:
    path.append(cell)
    cell = came[cell]
print(f"from {start} to {goal}: a path of {len(path)} cells")
GUI.showPath(path)

index = 0
while True:
    pose = HAL.getPose3d()
    if not path:
        HAL.setV(0)
        continue
    here = MAP.rowColumn([pose.x, pose.y])
    near = range(index, min(index + 30, len(path)))
    index = min(near, key=lambda i: abs(path[i][0] - here[0]) + abs(path[i][1] - here[1]))
    aim = GUI.gridToWorld(path[min(index + 8, len(path) - 1)])
    error = math.atan2(aim[1] - pose.y, aim[0] - pose.x) - pose.yaw
    error = math.atan2(math.sin(error), math.cos(error))
    HAL.setW(max(-1.0, min(1.0, 2.0 * error)))
    HAL.setV(0.0 if index >= len(path) - 2 else (4.0 if abs(error) < 0.3 else 0.5))
