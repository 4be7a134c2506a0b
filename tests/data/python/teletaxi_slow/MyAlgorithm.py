# teletaxi_follow's planner, slow but correct: 1.5 s of CPU at load (numpy and cv2 imported, as a
# slow machine takes them) and 3 s more in generatePath() (a heavy search). Within the default
# budgets (Component.StartBudget, Component.PlanBudget) it earns teletaxi_follow's report, byte for
# byte, however busy the machine: a mark never depends on how long the computing takes.
import importlib.util
import os
import time

import cv2  # noqa: F401  (what a planner brings)
import numpy  # noqa: F401


def burn(cpu_s):
    end = time.process_time() + cpu_s  # real CPU time, for profiling (the sim clock is time.time())
    n = 0
    while time.process_time() < end:
        n += 1


_spec = importlib.util.spec_from_file_location(
    "teletaxi_follow", os.path.join(os.path.dirname(__file__), "..", "teletaxi_follow", "MyAlgorithm.py"))
follow = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(follow)

burn(1.5)


class MyAlgorithm(follow.MyAlgorithm):
    def generatePath(self, api):
        burn(3.0)
        super().generatePath(api)
