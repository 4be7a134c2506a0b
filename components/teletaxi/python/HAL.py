# RoboticsAcademy's HAL for TeleTaxi (global_navigation_newmanager, ROS 2), on Aula's taxi:
# `import HAL` in a MyAlgorithm.py. Names, types and conventions are RoboticsAcademy's
# (aula_ra.py): a pose with .x, .y (m), .yaw (rad).
import aula_ra as _ra
from aula_ra import setV, setW  # m/s and rad/s, clamped to the exercise's MaxV and MaxW


# The taxi's pose: .x, .y (m), .yaw (rad, counter-clockwise from +x), .timeStamp (s).
def getPose3d():
    _ra.read("pose")
    return _ra.pose3d(_ra.api("HAL.getPose3d()").pose3d)


def __getattr__(name):
    _ra.missing("HAL", name, "getPose3d(), setV(v), setW(w)")
