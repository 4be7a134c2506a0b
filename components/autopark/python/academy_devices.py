# JdeRobot-Academy 2017-18's Autopark: MyAlgorithm(pose3d, laser1, laser2, laser3, motors) (host.py,
# aula_academy.py): laser1 the front laser, laser2 the back, laser3 the right, as Aula's api.
import aula_academy as _academy

ORDER = ("pose3d", "laser1", "laser2", "laser3", "motors")


def devices():
    return {"pose3d": _academy.Pose3dClient(), "laser1": _academy.LaserClient("laser1", "laser1"),
            "laser2": _academy.LaserClient("laser2", "laser2"), "laser3": _academy.LaserClient("laser3", "laser3"),
            "motors": _academy.MotorsClient()}
