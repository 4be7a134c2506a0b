# Your Autopark solution. execute() runs every Autopark.Period of simulated time.
#   api.pose3d.getX(), getY(), getYaw()   the car's centre (m) and heading (rad)
#   api.laser1 / laser2 / laser3          front, rear, right: getLaserData().values_m[i] (m, a
#                                         numpy array) or .distanceData[i] (mm), beam i at
#                                         .angle(i) (rad, -90..90 deg)
#   api.mount1 / mount2 / mount3          where each laser sits on the car (x forward, y left)
#   api.motors.sendV(v), sendW(w)         m/s and rad/s (clamped to Autopark.MaxV / MaxW)
#   api.status = "..."                    a line the window shows under the car's numbers
# Find the free slot beside the curb between the parked cars and park in it, parallel to the
# curb. The reference solutions: `aula run autopark --algorithm=reactive` or `--algorithm=planner`.
# The same API as MyAlgorithm.cpp, under the same names (aula_autopark.pyi, for your editor).
# Aula's Python has Debian's standard library, numpy and cv2.
# Time is the simulator's: time.time(), time.sleep() and datetime.now() are sim time (as
# api.time_s()), and time.perf_counter(); aula_profile.perf_counter() is real. A program of
# RoboticsAcademy (import HAL...) or JdeRobot-Academy runs here too: docs/exercises/from-roboticsacademy.md.
from aula_autopark import AutoparkApi


class MyAlgorithm:
    def __init__(self, seed: int) -> None:
        self.seed = seed

    def execute(self, api: AutoparkApi) -> None:
        # Example: drive slowly along the street and stop when something is close ahead.
        front = api.laser1.getLaserData()
        if front.numLaser == 0:
            return
        straight_ahead_m = float(front.values_m[front.numLaser // 2])
        api.motors.sendV(1.0 if straight_ahead_m > 3.0 else 0.0)
        api.motors.sendW(0.0)
