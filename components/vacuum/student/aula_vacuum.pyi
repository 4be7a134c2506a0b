# The vacuum cleaner's API (aula/vacuum/vacuum_algorithm.hpp) as MyAlgorithm.py sees it: stubs
# for your editor (with aula_devices.pyi beside it).
from aula_devices import Belief as Belief
from aula_devices import Bumper as Bumper
from aula_devices import BumperData as BumperData
from aula_devices import Laser as Laser
from aula_devices import LaserData as LaserData
from aula_devices import Motors as Motors
from aula_devices import Pose3d as Pose3d

class YawSensor:
    def getYaw(self) -> float: ...  # radians, CCW

class VacuumApi:
    @property
    def pose3d(self) -> YawSensor: ...  # getYaw() only: no localization in this exercise
    @property
    def laser(self) -> Laser: ...  # 180 beams over -90..90 degrees, m and mm
    @property
    def bumper(self) -> Bumper: ...  # getBumperData().state == 1 when pressed
    @property
    def motors(self) -> Motors: ...  # sendV(), sendW(), clamped to MaxV / MaxW
    @property
    def belief(self) -> Belief: ...  # setPose(), setMap(): what you believe, shown, never graded
    period_s: float  # the control period (sim seconds between execute() calls)
    # Sim time of this control period, seconds since the simulation started (= time.time()).
    def time_s(self) -> float: ...
