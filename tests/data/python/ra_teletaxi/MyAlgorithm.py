# A TeleTaxi wavefront planner written to RoboticsAcademy's page (global_navigation_newmanager,
# ROS 2): import HAL and GUI, GUI.getMap / getTargetPose / worldToGrid / gridToWorld /
# showPath, top-level planning, then `while True:` driving with time.sleep(). It runs unchanged
# on Aula (tests/integration/test_python_algorithms.cpp).
import GUI
import HAL
import time
import math
import numpy as np
import cv2

# --- plan: a wave from the target over the free cells, walls kept at a distance -------------
city = GUI.getMap('/resources/exercises/global_navigation/images/cityLargenBin.png')
target = GUI.getTargetPose()
while target is None:          # until the user picks a destination
    time.sleep(0.1)
    target = GUI.getTargetPose()
target_cell = GUI.worldToGrid(target)
pose = HAL.getPose3d()
start_cell = GUI.worldToGrid((pose.x, pose.y))
print("target", target, "cell", target_cell, "taxi cell", start_cell)

free = city > 127
clearance = cv2.distanceTransform(free.astype(np.uint8), cv2.DIST_L2, 3)   # cells to the nearest wall
step_cost = 1.0 + np.where(clearance < 4, (4 - clearance) * 3.0, 0.0)    # walls kept at a distance
rows, columns = city.shape
steps = [(1, 0, 1.0), (-1, 0, 1.0), (0, 1, 1.0), (0, -1, 1.0),
         (1, 1, 1.4), (1, -1, 1.4), (-1, 1, 1.4), (-1, -1, 1.4)]


# The wave, ring after ring from the target: each cell takes its cheapest neighbour plus its step,
# until the taxi's cell has a value and a few more rings have passed. The field is kept with a
# border of inf cells, so that a neighbour is a slice.
padded = np.full((rows + 2, columns + 2), np.inf, dtype=np.float32)
padded[target_cell[1] + 1, target_cell[0] + 1] = 0.0
inside = padded[1:-1, 1:-1]
step_costs = [(dx, dy, (step * step_cost).astype(np.float32)) for dx, dy, step in steps]
blocked = ~free
rings_after = None
for ring in range(4 * (rows + columns)):
    before = inside.copy()
    for dx, dy, cost_here in step_costs:
        neighbour = padded[1 + dy:rows + 1 + dy, 1 + dx:columns + 1 + dx]
        np.minimum(inside, neighbour + cost_here, out=inside)
    inside[blocked] = np.inf
    if rings_after is None and np.isfinite(inside[start_cell[1], start_cell[0]]):
        rings_after = ring + 20
    if np.array_equal(before, inside) or (rings_after is not None and ring >= rings_after):
        break
cost = inside.astype(np.float64)
reached = np.isfinite(cost[start_cell[1], start_cell[0]])
print("wave reached the taxi:", bool(reached), f"after {ring + 1} rings (CPU {time.process_time():.2f} s)")

# The path: down the wave from the taxi to the target.
path = [tuple(start_cell)]
x, y = start_cell
while (x, y) != tuple(target_cell) and len(path) < 5000:
    best = min(((cost[y + dy, x + dx], x + dx, y + dy) for dx, dy, _ in steps
                if 0 <= x + dx < columns and 0 <= y + dy < rows), default=None)
    if best is None or not best[0] < cost[y, x]:
        break
    _, x, y = best
    path.append((x, y))
GUI.showPath(path)
print("path of", len(path), "cells")

# --- drive: towards a point a few cells ahead on the path -----------------------------------
LOOKAHEAD = 6
index = 0
started = time.time()
while True:
    pose = HAL.getPose3d()
    here = np.array([pose.x, pose.y])
    # The nearest path cell from where we got to, a little way on.
    window = path[index:index + 40]
    distances = [np.linalg.norm(here - np.array(GUI.gridToWorld(cell))) for cell in window]
    index += int(np.argmin(distances))
    goal = np.array(GUI.gridToWorld(path[min(index + LOOKAHEAD, len(path) - 1)]))
    to_target = np.linalg.norm(here - np.array(target))
    if to_target < 1.5:
        HAL.setV(0)
        HAL.setW(0)
        print(f"arrived in {time.time() - started:.1f} s, {to_target:.2f} m from the target")
        break
    heading = math.atan2(goal[1] - pose.y, goal[0] - pose.x)
    error = math.atan2(math.sin(heading - pose.yaw), math.cos(heading - pose.yaw))
    HAL.setW(2.0 * error)
    HAL.setV(8.0 if abs(error) < 0.2 else (3.0 if abs(error) < 0.6 else 0.5))
    if to_target < 10:
        HAL.setV(min(3.0, to_target))
    time.sleep(0.08)

while True:       # stay put once there
    HAL.setV(0)
    HAL.setW(0)
    time.sleep(1)
