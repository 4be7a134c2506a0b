# JdeRobot-Academy 2017-18's TeleTaxi: MyAlgorithm(grid, sensor, vel) (host.py, aula_academy.py).
# grid is Aula's api.grid (the original's names: getMap, getDestiny, getPose, setVal, getVal,
# setPathVal, getPathVal, setPathFinded, showGrid, worldToGrid, gridToWorld...); sensor gives the
# taxi's pose (getRobotX/Y/Theta, getPose3D) and getPathSig, the "Generate Path" button's signal
# (what the program connects to it is run there); vel sets the speeds (setV, setW).
import aula_academy as _academy
import aula_ra as _ra

ORDER = ("grid", "sensor", "vel")


class Grid:
    """api.grid of the call now running, under its own (the original's) names."""

    def __getattr__(self, name):
        return getattr(_ra.api(f"grid.{name}").grid, name)


class PathSignal:
    """The original's Qt signal: connect(slot) keeps it; Aula runs the slots at "Generate Path"."""

    def __init__(self):
        self.slots = []

    def connect(self, slot):
        self.slots.append(slot)

    def emit(self, *unused):
        for slot in list(self.slots):
            slot()


class Sensor(_academy.Pose3dClient):
    def __init__(self):
        super().__init__("sensor", "sensor")
        self.getPathSig = PathSignal()

    def getRobotX(self):
        return self.getX()

    def getRobotY(self):
        return self.getY()

    def getRobotTheta(self):
        return self.getYaw()


def devices():
    return {"grid": Grid(), "sensor": Sensor(), "vel": _academy.MotorsClient("vel", "vel")}
