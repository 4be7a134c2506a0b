# JdeRobot-Academy 2017-18's shape: a threading.Thread made with (pose3d, motors, laser, bumper),
# its own run() calling execute() every time_cycle ms, play()/stop()/kill(); `import jderobot`.
# The laser's distanceData in millimetres, the yaw from pose3d; a spiral, then bump and turn.
import math
import threading
import time
from datetime import datetime

import jderobot
import numpy as np

time_cycle = 80


class MyAlgorithm(threading.Thread):

    def __init__(self, pose3d, motors, laser, bumper):
        self.pose3d = pose3d
        self.motors = motors
        self.laser = laser
        self.bumper = bumper
        self.stop_event = threading.Event()
        self.kill_event = threading.Event()
        self.lock = threading.Lock()
        threading.Thread.__init__(self, args=self.stop_event)
        self.turning_until = None
        self.calls = 0

    def run(self):
        while not self.kill_event.is_set():
            start_time = datetime.now()
            if not self.stop_event.is_set():
                self.execute()
            finish_time = datetime.now()
            dt = finish_time - start_time
            ms = (dt.days * 24 * 60 * 60 + dt.seconds) * 1000 + dt.microseconds / 1000.0
            if ms < time_cycle:
                time.sleep((time_cycle - ms) / 1000.0)

    def stop(self):
        self.motors.sendV(0)
        self.motors.sendAZ(0)
        self.stop_event.set()

    def play(self):
        if self.is_alive():
            self.stop_event.clear()
        else:
            self.start()

    def kill(self):
        self.kill_event.set()

    def execute(self):
        self.calls += 1
        data = self.laser.getLaserData()
        front_mm = np.min(data.distanceData[data.numLaser // 3: 2 * data.numLaser // 3])
        yaw = self.pose3d.getPose3d().yaw
        now = time.time()
        if self.bumper.getBumperData().state == 1 or front_mm < 250:
            self.turning_until = now + 1.2
        if self.turning_until is not None and now < self.turning_until:
            self.motors.sendV(-0.05)
            self.motors.sendAZ(0.9)
        else:
            self.motors.sendV(0.3)
            self.motors.sendW(0.25 / (1.0 + 0.05 * self.calls ** 0.5))
        if self.calls % 100 == 0:
            print(f"call {self.calls} at {now:.2f} s, yaw {math.degrees(yaw):.0f} deg, front {front_mm} mm")
