# JdeRobot-Academy 2017-18's Autopark shape: a threading.Thread made with (pose3d, laser1, laser2,
# laser3, motors), the template's run()/play()/stop()/kill() left out (as some students did):
# execute() every time_cycle ms all the same. pose3d.getPose3d().x/.yaw and getX(), the lasers'
# distanceData in millimetres. Ahead 10 m on the lane, then stops (and says so once).
import threading
import time

import jderobot

time_cycle = 80


class MyAlgorithm(threading.Thread):

    def __init__(self, pose3d, laser1, laser2, laser3, motors):
        self.pose3d = pose3d
        self.laser1 = laser1
        self.laser2 = laser2
        self.laser3 = laser3
        self.motors = motors
        self.stop_event = threading.Event()
        self.kill_event = threading.Event()
        threading.Thread.__init__(self, args=self.stop_event)
        self.start_x = None

    def execute(self):
        pose = self.pose3d.getPose3d()
        if self.start_x is None:
            self.start_x = self.pose3d.getX()
        front_mm = min(self.laser1.getLaserData().distanceData[80:100])
        right_mm = min(self.laser3.getLaserData().distanceData)
        back_mm = min(self.laser2.getLaserData().distanceData)
        if pose.x - self.start_x < 10.0 and front_mm > 2000:
            self.motors.sendV(1.0)
            self.motors.sendW(-0.8 * pose.yaw)
        else:
            self.motors.sendV(0)
            self.motors.sendW(0)
            if not self.stop_event.is_set():
                print(f"stopped at x {pose.x:.2f} m: front {front_mm} mm, right {right_mm} mm, back {back_mm} mm")
            self.stop_event.set()
