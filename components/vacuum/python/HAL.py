# RoboticsAcademy's HAL for the vacuum cleaner (vacuum_cleaner_newmanager, ROS 2), on Aula's
# robot: `import HAL` in a MyAlgorithm.py. Names, types and conventions are RoboticsAcademy's
# (aula_ra.py): the laser's .values in metres from 0 (right) to pi (left), the bumper's 0 = right.
# Aula's vacuum is not told where it is: getPose3d() gives the yaw only.
import aula_ra as _ra
from aula_ra import setV, setW  # m/s and rad/s, clamped to the exercise's MaxV and MaxW

RIGHT_BUMPER, CENTER_BUMPER, LEFT_BUMPER = _ra.RIGHT_BUMPER, _ra.CENTER_BUMPER, _ra.LEFT_BUMPER


# The laser: 180 beams over 180 degrees, .values in metres, beam 0 on the right.
def getLaserData():
    _ra.read("laser")
    return _ra.laser_data(_ra.api("HAL.getLaserData()").laser.getLaserData())


# The heading only: .yaw (rad) and .timeStamp (s); .x and .y say that the vacuum has no localization.
def getPose3d():
    _ra.read("pose")
    api = _ra.api("HAL.getPose3d()")
    return _ra.YawOnlyPose3d(api.pose3d.getYaw(), api.time_s(), "vacuum cleaner")


# .state 1 while touching; .bumper RIGHT_BUMPER 0, CENTER_BUMPER 1, LEFT_BUMPER 2.
def getBumperData():
    _ra.read("bumper")
    return _ra.bumper_data(_ra.api("HAL.getBumperData()").bumper.getBumperData())


def __getattr__(name):
    _ra.missing("HAL", name, "getLaserData(), getPose3d() (.yaw only), getBumperData(), setV(v), setW(w)")
