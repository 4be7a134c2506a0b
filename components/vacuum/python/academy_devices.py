# JdeRobot-Academy 2017-18's vacuum: MyAlgorithm(pose3d, motors, laser, bumper) (host.py,
# aula_academy.py). pose3d gives the yaw only: Aula's vacuum is not told where it is.
import aula_academy as _academy

ORDER = ("pose3d", "motors", "laser", "bumper")


def devices():
    return {"pose3d": _academy.YawOnlyPose3dClient("vacuum cleaner"), "motors": _academy.MotorsClient(),
            "laser": _academy.LaserClient("laser", "laser"), "bumper": _academy.BumperClient("bumper", "bumper")}
