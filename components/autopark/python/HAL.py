# RoboticsAcademy's HAL for Autopark (autoparking_newmanager, ROS 2), on Aula's car: `import HAL`
# in a MyAlgorithm.py. Names, types and conventions are RoboticsAcademy's (aula_ra.py): each
# laser's .values in metres from 0 (its right) to pi (its left), poses with .x, .y, .yaw.
# The lasers sit on the car as Autopark's page draws them: front (its nose, looking ahead), right
# (its right side, looking right), back (its tail, looking behind).
import aula_ra as _ra
from aula_ra import setV, setW  # m/s and rad/s, clamped to the exercise's MaxV and MaxW


# The car's pose: .x, .y (m, the car's centre), .yaw (rad), .timeStamp (s).
def getPose3d():
    _ra.read("pose")
    return _ra.pose3d(_ra.api("HAL.getPose3d()").pose3d)


# As in RoboticsAcademy, a laser's first read waits until its first scan has arrived.
def _laser(name, what):
    _ra.read(name)
    _ra.wait_until(lambda: getattr(_ra.api(what), name).received())
    return _ra.laser_data(getattr(_ra.api(what), name).getLaserData())


# The front laser: 180 beams over 180 degrees, beam 0 on the car's right.
def getFrontLaserData():
    return _laser("laser1", "HAL.getFrontLaserData()")


# The right laser: beam 0 towards the car's back, the middle beam straight out to the right.
def getRightLaserData():
    return _laser("laser3", "HAL.getRightLaserData()")


# The back laser: looking behind, beam 0 on the car's left (the laser's own right).
def getBackLaserData():
    return _laser("laser2", "HAL.getBackLaserData()")


def __getattr__(name):
    _ra.missing("HAL", name, "getPose3d(), getFrontLaserData(), getRightLaserData(), getBackLaserData(), "
                "setV(v), setW(w)")
