# The devices of every exercise's API (components/common/include/aula/component/devices.hpp),
# as Aula's embedded Python sees them: the same C++ objects under the same names. Stubs only,
# for your editor: at run time each exercise's module (aula_vacuum, aula_teletaxi,
# aula_autopark) holds these classes.
from typing import Any
import numpy as np
import numpy.typing as npt

class Pose3d:
    def getX(self) -> float: ...  # metres
    def getY(self) -> float: ...  # metres
    def getYaw(self) -> float: ...  # radians, counter-clockwise from +x
    # TeleTaxi's original names.
    def getRobotX(self) -> float: ...
    def getRobotY(self) -> float: ...
    def getRobotTheta(self) -> float: ...
    def received(self) -> bool: ...
    def utime(self) -> int: ...  # sim time of the reading, microseconds

class LaserData:
    # Beam i at minAngle + i * angleIncrement. Read-only numpy views of the C++ scan (no copy):
    # a view you keep always shows the latest scan; .copy() it to keep one.
    @property
    def values_m(self) -> npt.NDArray[np.float32]: ...  # metres
    @property
    def distanceData(self) -> npt.NDArray[np.int32]: ...  # the same ranges in millimetres
    numLaser: int
    minAngle: float  # radians
    maxAngle: float
    angleIncrement: float
    minRange: float  # metres
    maxRange: float
    timeStamp: int  # sim time, microseconds
    def angle(self, i: int) -> float: ...  # beam i's angle, radians

class Laser:
    def getLaserData(self) -> LaserData: ...
    def received(self) -> bool: ...

class BumperData:
    bumper: int  # 0 left, 1 centre, 2 right
    state: int  # 1 pressed
    timeStamp: int

class Bumper:
    def getBumperData(self) -> BumperData: ...

class Motors:
    # Clamped to the exercise's MaxV / MaxW; a NaN or infinite command sets that axis to 0 and
    # is counted in the report.
    def sendV(self, v_mps: float) -> None: ...
    def sendW(self, w_radps: float) -> None: ...
    def sendL(self, l_mps: float) -> None: ...
    # TeleTaxi's original names.
    def setV(self, v_mps: float) -> None: ...
    def setW(self, w_radps: float) -> None: ...
    def stop(self) -> None: ...
    def getV(self) -> float: ...
    def getW(self) -> float: ...
    def getL(self) -> float: ...
    def maxV(self) -> float: ...
    def maxW(self) -> float: ...

class Belief:
    # What your algorithm believes (never graded): the window draws it in magenta beside the
    # truth, the run's log keeps it. Your own frame: put your start where you like (0, 0).
    def setPose(self, x_m: float, y_m: float, yaw_rad: float) -> None: ...
    # cells: a 2-D array (row r, column c is the cell at x = origin_x_m + c * resolution_m,
    # y = origin_y_m + r * resolution_m), each 0 (free) .. 255 (occupied), 128 unknown.
    def setMap(self, cells: Any, resolution_m: float, origin_x_m: float = 0.0, origin_y_m: float = 0.0) -> None: ...

