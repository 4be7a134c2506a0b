# A TeleTaxi planner in RoboticsAcademy's shape that trusts RA's map constants instead of
# GUI.worldToGrid: the 400 x 400 map of the 500 x 500 m city, column from world y and row from
# world x, `(y + 250) * 400 / 500`, and back `x = row * 500 / 400 - 250`. A breadth-first search
# from the target over the free cells kept 2 cells off the walls, then a pure pursuit along it.
# Written for Aula's tests (tests/integration/test_python_algorithms.cpp), not a student's.
import GUI
import HAL
import time
import math
from collections import deque

import numpy as np

SIZE, WORLD = 400, 500.0


def to_cell(x, y):                    # (column, row), as RA's map class
    return int((y + 250) * SIZE / WORLD), int((x + 250) * SIZE / WORLD)


def to_world(cell):                   # the cell's centre
    column, row = cell
    return row * WORLD / SIZE - 250 + 0.625, column * WORLD / SIZE - 250 + 0.625


city = GUI.getMap('/resources/exercises/global_navigation/images/cityLargenBin.png')
if city.shape != (SIZE, SIZE):
    raise SystemExit(f"the map is {city.shape}, RA's is 400 x 400")
target = GUI.getTargetPose()
while target is None:
    time.sleep(0.1)
    target = GUI.getTargetPose()
pose = HAL.getPose3d()
start, goal = to_cell(pose.x, pose.y), to_cell(target[0], target[1])

# Free cells at least 2 cells from a wall (so the taxi's 4 m body keeps off the buildings).
free = city > 127
safe = free.copy()
for dr in range(-2, 3):
    for dc in range(-2, 3):
        safe &= np.roll(np.roll(free, dr, axis=0), dc, axis=1)
safe[goal[1], goal[0]] = safe[start[1], start[0]] = True

# Breadth-first from the goal: steps to the goal, -1 where unreached.
steps = np.full(city.shape, -1, dtype=np.int32)
steps[goal[1], goal[0]] = 0
queue = deque([goal])
while queue:
    column, row = queue.popleft()
    for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        c, r = column + dc, row + dr
        if 0 <= c < SIZE and 0 <= r < SIZE and safe[r, c] and steps[r, c] < 0:
            steps[r, c] = steps[row, column] + 1
            queue.append((c, r))
if steps[start[1], start[0]] < 0:
    raise SystemExit(f"no way from cell {start} to cell {goal}")
path = [start]
while path[-1] != goal:
    column, row = path[-1]
    path.append(min(((column + dc, row + dr) for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1))
                     if 0 <= column + dc < SIZE and 0 <= row + dr < SIZE and steps[row + dr, column + dc] >= 0),
                    key=lambda cell: steps[cell[1], cell[0]]))
print(f"path of {len(path)} cells from {start} to {goal} (by RA's constants)")
GUI.showPath(path)

index = 0
while True:
    pose = HAL.getPose3d()
    to_target = math.hypot(target[0] - pose.x, target[1] - pose.y)
    if to_target < 1.5:
        HAL.setV(0)
        HAL.setW(0)
        print(f"arrived, {to_target:.2f} m from the target")
        break
    near = min(range(index, min(index + 30, len(path))),
               key=lambda i: math.hypot(to_world(path[i])[0] - pose.x, to_world(path[i])[1] - pose.y))
    index = near
    aim = to_world(path[min(index + 5, len(path) - 1)])
    error = math.atan2(aim[1] - pose.y, aim[0] - pose.x) - pose.yaw
    error = math.atan2(math.sin(error), math.cos(error))
    HAL.setW(2.0 * error)
    HAL.setV(min(6.0 if abs(error) < 0.3 else 1.0, max(0.5, to_target)))
    time.sleep(0.05)

while True:
    time.sleep(1)
