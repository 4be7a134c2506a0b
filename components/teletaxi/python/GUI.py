# RoboticsAcademy's GUI for TeleTaxi (global_navigation_newmanager), on Aula's city and window:
# `import GUI` in a MyAlgorithm.py. A cell is (column, row) of the map image, as RoboticsAcademy's
# worldToGrid gives it (its gridX, gridY), and the image is indexed map[row, column].
# Aula's city map is generated from the world, with its own transform (not RoboticsAcademy's
# 400 x 400 picture of a 500 x 500 m city): go through worldToGrid/gridToWorld, as
# RoboticsAcademy's page says, and the program works on both.
import numpy as _np

import aula_ra as _ra


def _grid(what):
    return _ra.api(what).grid


# The city map as a numpy uint8 image [row, column]: 0 obstacle, 255 free. `url` (RoboticsAcademy's
# picture's path) is accepted and not used: the map is the world's own. A copy: yours to change.
def getMap(url=None):
    return _np.array(_grid("GUI.getMap()").getMap(), dtype=_np.uint8, copy=True)


# The destination the user chose, in world metres (x, y): the centre of its cell; None until chosen.
def getTargetPose():
    grid = _grid("GUI.getTargetPose()")
    cell = grid.getDestiny()
    if cell[0] < 0 or cell[1] < 0:
        return None
    return grid.gridToWorld(int(cell[0]), int(cell[1]))


# World (x, y) in metres -> (column, row) of the map.
def worldToGrid(pose):
    x, y = pose[0], pose[1]
    return tuple(_grid("GUI.worldToGrid()").worldToGrid(float(x), float(y)))


# (column, row) of the map -> world (x, y) in metres, the cell's centre.
def gridToWorld(cell):
    return tuple(_grid("GUI.gridToWorld()").gridToWorld(int(cell[0]), int(cell[1])))


# Deprecated in RoboticsAcademy (worldToGrid as a list), kept as there.
def rowColumn(pose):
    return list(worldToGrid(pose))


# Draws the path on the map: a list of cells (column, row), as worldToGrid gives them.
def showPath(array):
    grid = _grid("GUI.showPath()")
    grid.resetPath()
    width, height = grid.getWidth(), grid.getHeight()
    for cell in array:
        column, row = int(cell[0]), int(cell[1])
        if 0 <= column < width and 0 <= row < height:
            grid.setPathVal(column, row, 1.0)
    grid.setPathFinded()


# Shows a 2-D numpy image (your field, say) in the "Grid Field" window: it becomes the grid's
# field, drawn dark to light, as api.grid.field().
def showNumpy(image):
    grid = _grid("GUI.showNumpy()")
    image = _np.asarray(image, dtype=_np.float32)
    field = grid.field()
    if image.shape != field.shape:
        raise ValueError(f"GUI.showNumpy(): an image of {image.shape[0]} x {image.shape[1]}, the map is "
                         f"{field.shape[0]} x {field.shape[1]} (rows x columns)")
    field[:, :] = image
    grid.showGrid()


def __getattr__(name):
    _ra.missing("GUI", name, "getMap(url), getTargetPose(), worldToGrid((x, y)), gridToWorld((column, row)), "
                "rowColumn(pose), showPath(cells), showNumpy(image)")
