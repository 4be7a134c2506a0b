# Turns by random draws from `random`, numpy's global generator and an unseeded default_rng():
# all seeded from the run's seed before the file runs, the same seed gives the same report.
import random

import numpy as np


class MyAlgorithm:
    def __init__(self, seed):
        self.seed = seed
        self.left = 0
        self.rng = np.random.default_rng()

    def execute(self, api):
        if self.left <= 0:
            self.v = random.uniform(0.1, 0.5)
            self.w = float(np.random.uniform(-1.0, 1.0)) * float(self.rng.uniform(0.5, 1.0))
            self.left = 10
        self.left -= 1
        api.motors.sendV(self.v)
        api.motors.sendW(self.w)
