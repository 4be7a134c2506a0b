# Tells its belief (api.belief): a pose from the yaw and its own odometry, and a small map made
# with numpy; on its 50th call it gives setMap a 1-D array (line 23), which is a ValueError.
import math

import numpy as np


class MyAlgorithm:
    def __init__(self, seed):
        self.calls = 0
        self.x = self.y = 0.0

    def execute(self, api):
        self.calls += 1
        yaw = api.pose3d.getYaw()
        self.x += 0.2 * api.period_s * math.cos(yaw)
        self.y += 0.2 * api.period_s * math.sin(yaw)
        api.motors.sendV(0.2)
        api.belief.setPose(self.x, self.y, yaw)
        if self.calls == 10:
            api.belief.setMap(np.full((3, 4), 128, dtype=np.uint8), 0.5, -1.0, -0.75)
        if self.calls == 50:
            api.belief.setMap(np.zeros(12), 0.5)
