# =============================================================================================
#  Vacuum cleaner: YOUR algorithm goes here. Clean as much of the house as you can in 900 s.
#
#  execute(api) runs every control period (api.period_s, 80 ms of simulated time):
#      api.pose3d.getYaw()                  heading, radians (there is no x, y: no localization!)
#      api.laser.getLaserData()             .values_m (metres, a numpy array) / .distanceData (mm),
#                                           180 beams, beam i at .angle(i), from -pi/2 (right) to
#                                           +pi/2 (left)
#      api.bumper.getBumperData().state     1 while the bumper is pressed
#      api.motors.sendV(v_mps), sendW(w_radps)   clamped to MaxV / MaxW of the .cfg
#
#  The same API as MyAlgorithm.cpp, under the same names (aula_vacuum.pyi, for your editor).
#  `random` and numpy's generator are seeded with the run's seed (aula run --seed) before
#  __init__(seed): the same seed, the same run. Aula's Python has Debian's standard library,
#  numpy and cv2.
#  Time is the simulator's: time.time(), time.sleep() and datetime.now() are sim time (as
#  api.time_s()), and time.perf_counter(); aula_profile.perf_counter() is real. A program of
#  RoboticsAcademy (import HAL...) or JdeRobot-Academy runs here too: docs/exercises/from-roboticsacademy.md.
#
#  Ideas from real Roombas: an outward spiral, following walls, crossing rooms with random
#  turns, escaping from corners. Until you write something, this template stays still.
# =============================================================================================
from aula_vacuum import VacuumApi


class MyAlgorithm:
    def __init__(self, seed: int) -> None:
        self.seed = seed

    def execute(self, api: VacuumApi) -> None:
        # TODO: your cleaning strategy.
        api.motors.sendV(0.0)
        api.motors.sendW(0.0)
