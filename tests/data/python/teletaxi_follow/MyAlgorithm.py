# The Python port of tests/data/plugins/teletaxi_follow.cpp, line by line: the same report for
# the same destination proves that the two languages see one API (the grid included).
from collections import deque
import math

import numpy as np

STEPS = ((1, 0), (-1, 0), (0, 1), (0, -1))
MARGIN = 2  # cells


def wrap(a):
    while a > math.pi:
        a -= 2 * math.pi
    while a < -math.pi:
        a += 2 * math.pi
    return a


def distance_to(p, x, y):
    dx, dy = p[0] - x, p[1] - y
    return math.sqrt(dx * dx + dy * dy)


class MyAlgorithm:
    def __init__(self, seed):
        self.path = []
        self.progress = 0

    def generatePath(self, api):
        grid = api.grid
        width, height = grid.getWidth(), grid.getHeight()
        gx, gy = grid.getDestiny()
        px, py = grid.getPose()
        free = grid.getMap() != 0  # numpy, over the C++ map
        field = grid.field()       # numpy, over the C++ field: written in place
        # Clear: free, and MARGIN cells from any obstacle (outside the map counts as one).
        padded = np.zeros((height + 2 * MARGIN, width + 2 * MARGIN), dtype=bool)
        padded[MARGIN:MARGIN + height, MARGIN:MARGIN + width] = free
        clear = np.ones((height, width), dtype=bool)
        for dy in range(-MARGIN, MARGIN + 1):
            for dx in range(-MARGIN, MARGIN + 1):
                clear &= padded[MARGIN + dy:MARGIN + dy + height, MARGIN + dx:MARGIN + dx + width]
        clear = clear.ravel().tolist()
        distance = [-1] * (width * height)
        wave = deque()
        if clear[gy * width + gx]:
            distance[gy * width + gx] = 0
            wave.append((gx, gy))
        while wave:
            x, y = wave.popleft()
            d = distance[y * width + x]
            field[y, x] = d
            for sx, sy in STEPS:
                nx, ny = x + sx, y + sy
                if 0 <= nx < width and 0 <= ny < height and clear[ny * width + nx] and distance[ny * width + nx] < 0:
                    distance[ny * width + nx] = d + 1
                    wave.append((nx, ny))
        self.path = []
        self.progress = 0
        # The taxi may stand closer to a wall than the margin: start from the first reached cell around it.
        x, y = -1, -1
        for r in range(5):
            for dy in range(-r, r + 1):
                for dx in range(-r, r + 1):
                    cx, cy = px + dx, py + dy
                    if x < 0 and 0 <= cx < width and 0 <= cy < height and distance[cy * width + cx] >= 0:
                        x, y = cx, cy
            if x >= 0:
                break
        if x < 0:
            return
        while True:
            grid.setPathVal(x, y, 1.0)
            self.path.append(grid.gridToWorld(x, y))
            d = distance[y * width + x]
            if d == 0:
                break
            for sx, sy in STEPS:
                nx, ny = x + sx, y + sy
                if 0 <= nx < width and 0 <= ny < height and distance[ny * width + nx] == d - 1:
                    x, y = nx, ny
                    break
        grid.setPathFinded()

    def execute(self, api):
        x, y, yaw = api.sensor.getRobotX(), api.sensor.getRobotY(), api.sensor.getRobotTheta()
        if not self.path:
            api.vel.setV(0.0)
            api.vel.setW(0.0)
            return
        last = len(self.path) - 1
        # The closest point a little ahead (the taxi cuts corners), then past what is near.
        window_end = min(self.progress + 20, last)
        for i in range(self.progress + 1, window_end + 1):
            if distance_to(self.path[i], x, y) < distance_to(self.path[self.progress], x, y):
                self.progress = i
        while self.progress < last and distance_to(self.path[self.progress], x, y) < 4.0:
            self.progress += 1
        target = self.path[min(self.progress + 6, last)]
        to_goal = distance_to(self.path[last], x, y)
        error = wrap(math.atan2(target[1] - y, target[0] - x) - yaw)
        v, w = 0.0, 0.0
        if to_goal > 1.0:
            v = min(6.0, 0.5 + 0.5 * to_goal) * max(0.0, math.cos(error))
            w = 2.0 * error
        api.vel.setV(v)
        api.vel.setW(w)
