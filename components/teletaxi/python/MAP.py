# RoboticsAcademy 2021-23's MAP for Global Navigation (`from MAP import MAP`): the city map and
# the world-to-map transform, the same as GUI's: RoboticsAcademy's 400 x 400 picture (GUI.py).
import GUI as _GUI
import aula_ra as _ra


# The city map, a 400 x 400 numpy uint8 image [row, column]: 0 obstacle, 255 free (`url` is not used).
def getMap(url=None):
    return _GUI.getMap(url)


# World (x, y) in metres -> [column, row] of the map, as RoboticsAcademy's rowColumn.
def rowColumn(pose):
    return _GUI.rowColumn(pose)


def __getattr__(name):
    _ra.missing("MAP", name, "getMap(url), rowColumn(pose); GUI has worldToGrid and gridToWorld")
