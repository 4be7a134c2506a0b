# Turns by random draws from `random` and numpy's global generator: seeded from the run's seed
# before __init__, the same seed gives the same report.
import random

import numpy as np


class MyAlgorithm:
    def __init__(self, seed):
        self.seed = seed
        self.left = 0

    def execute(self, api):
        if self.left <= 0:
            self.v = random.uniform(0.1, 0.5)
            self.w = float(np.random.uniform(-1.0, 1.0))
            self.left = 10
        self.left -= 1
        api.motors.sendV(self.v)
        api.motors.sendW(self.w)
