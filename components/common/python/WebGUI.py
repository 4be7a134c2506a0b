# RoboticsAcademy 2025's WebGUI (`import WebGUI`): the exercise's GUI under its new name
# (TeleTaxi: getMap, showNumpy, showPath, getTargetPose, worldToGrid, gridToWorld, rowColumn).
import GUI as _GUI


def __getattr__(name):
    return getattr(_GUI, name)
