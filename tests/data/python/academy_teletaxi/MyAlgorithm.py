# JdeRobot-Academy 2017-18's TeleTaxi shape: `from sensors import sensor`, a threading.Thread made
# with (grid, sensor, vel) that connects generatePath to sensor.getPathSig; generatePath() spreads
# a wave from the destination with grid.setVal, marks the path with setPathVal and setPathFinded;
# execute() (every time_cycle ms, from its own run()) follows it with sensor.getRobotX/Y/Theta
# and vel.setV/setW.
from collections import deque
import math
import threading
import time
from datetime import datetime

import numpy as np
from sensors import sensor

time_cycle = 80


class MyAlgorithm(threading.Thread):

    def __init__(self, grid, sensor, vel):
        self.sensor = sensor
        self.grid = grid
        self.vel = vel
        sensor.getPathSig.connect(self.generatePath)
        self.stop_event = threading.Event()
        self.kill_event = threading.Event()
        self.lock = threading.Lock()
        threading.Thread.__init__(self, args=self.stop_event)
        self.path = []

    def run(self):
        while not self.kill_event.is_set():
            start_time = datetime.now()
            if not self.stop_event.is_set():
                self.execute()
            dt = datetime.now() - start_time
            ms = (dt.days * 24 * 60 * 60 + dt.seconds) * 1000 + dt.microseconds / 1000.0
            if ms < time_cycle:
                time.sleep((time_cycle - ms) / 1000.0)

    def stop(self):
        self.stop_event.set()

    def play(self):
        if self.is_alive():
            self.stop_event.clear()
        else:
            self.start()

    def kill(self):
        self.kill_event.set()

    def generatePath(self):
        print("LOOKING FOR SHORTER PATH")
        city = self.grid.getMap()
        destiny = tuple(self.grid.getDestiny())
        taxi = tuple(self.grid.getPose())
        wave = {destiny: 0}
        queue = deque([destiny])
        while queue and taxi not in wave:
            x, y = queue.popleft()
            for nx, ny in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
                if (nx, ny) not in wave and 0 <= ny < city.shape[0] and 0 <= nx < city.shape[1] and \
                        (city[ny, nx] > 127 or (nx, ny) == taxi):
                    wave[(nx, ny)] = wave[(x, y)] + 1
                    self.grid.setVal(nx, ny, wave[(nx, ny)])
                    queue.append((nx, ny))
        cell = taxi if taxi in wave else None
        while cell is not None and cell != destiny:
            self.path.append(cell)
            self.grid.setPathVal(cell[0], cell[1], 1)
            cell = min(((cell[0] + dx, cell[1] + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))),
                       key=lambda c: wave.get(c, math.inf))
        self.path.append(destiny)
        self.grid.setPathFinded()
        self.grid.showGrid()
        print("path of", len(self.path), "cells")

    def execute(self):
        x, y, theta = self.sensor.getRobotX(), self.sensor.getRobotY(), self.sensor.getRobotTheta()
        here = self.grid.worldToGrid(x, y)
        if len(self.path) < 2:
            self.vel.setV(0)
            return
        nearest = min(range(len(self.path)), key=lambda i: abs(self.path[i][0] - here[0]) + abs(self.path[i][1] - here[1]))
        aim = self.grid.gridToWorld(*self.path[min(nearest + 6, len(self.path) - 1)])
        error = math.atan2(aim[1] - y, aim[0] - x) - theta
        error = math.atan2(math.sin(error), math.cos(error))
        self.vel.setW(max(-1.0, min(1.0, 2.0 * error)))
        self.vel.setV(0 if nearest >= len(self.path) - 2 else (3.0 if abs(error) < 0.3 else 0.5))
