# RoboticsAcademy's GUI for TeleTaxi (global_navigation_newmanager), on Aula's city and window:
# `import GUI` in a MyAlgorithm.py. The map and the cells are RoboticsAcademy's: a 400 x 400
# picture of the 500 x 500 m city, indexed map[row, column], where worldToGrid gives (column, row)
# = ((y + 250) * 400 / 500, (x + 250) * 400 / 500): the column from world y, the row from world x,
# and gridToWorld((column, row)) = (row * 500 / 400 - 250, column * 500 / 400 - 250). A program that
# hard-codes these constants lands on the same world point as one that calls worldToGrid. The
# picture is resampled from Aula's own map (api.grid, its own transform: TeleTaxi.Map.Resolution).
import numpy as _np

import aula_ra as _ra

RA_MAP_PX = 400      # RoboticsAcademy's map picture, cells a side
RA_WORLD_M = 500.0   # the city it shows, metres a side, centred on the origin
RA_CELL_M = RA_WORLD_M / RA_MAP_PX  # 1.25 m


def _grid(what):
    return _ra.api(what).grid


def _aula_cells(grid, x_m, y_m):
    """Aula's (columns, rows) of world points (numpy arrays), from two of its cells' centres."""
    x0, y0 = grid.gridToWorld(0, 0)
    x1, y1 = grid.gridToWorld(1, 1)
    dx, dy = x1 - x0, y1 - y0  # metres per column and per row (dy < 0: row 0 at the top)
    columns = _np.floor((x_m - (x0 - dx / 2)) / dx).astype(_np.int64)
    rows = _np.floor((y_m - (y0 - dy / 2)) / dy).astype(_np.int64)
    return columns, rows


_ra_map = None  # the resampled picture, made once: the city does not change


def _picture(what):
    """RoboticsAcademy's 400 x 400 picture [row, column] from Aula's map: a cell is an obstacle
    if any of nine points spread over it is one in Aula's map (or off it), so no street narrower
    than Aula's shows through a corner."""
    global _ra_map
    if _ra_map is None:
        grid = _grid(what)
        aula = _np.asarray(grid.getMap())
        index = _np.arange(RA_MAP_PX, dtype=_np.float64)
        picture = _np.full((RA_MAP_PX, RA_MAP_PX), 255, dtype=_np.uint8)
        for fx in (1 / 6, 0.5, 5 / 6):
            for fy in (1 / 6, 0.5, 5 / 6):
                x_m = (index[:, None] + fx) * RA_CELL_M - RA_WORLD_M / 2  # rows: world x
                y_m = (index[None, :] + fy) * RA_CELL_M - RA_WORLD_M / 2  # columns: world y
                columns, rows = _aula_cells(grid, _np.broadcast_to(x_m, picture.shape), _np.broadcast_to(y_m, picture.shape))
                inside = (columns >= 0) & (rows >= 0) & (columns < aula.shape[1]) & (rows < aula.shape[0])
                value = _np.zeros(picture.shape, dtype=_np.uint8)
                value[inside] = aula[rows[inside], columns[inside]]
                _np.minimum(picture, _np.where(value > 127, 255, 0).astype(_np.uint8), out=picture)
        _ra_map = picture
    return _ra_map


# The city map as a numpy uint8 image [row, column], 400 x 400: 0 obstacle, 255 free. `url`
# (RoboticsAcademy's picture's path) is accepted and not used: the map is the world's own. A copy:
# yours to change.
def getMap(url=None):
    return _picture("GUI.getMap()").copy()


# The destination the user chose, in world metres (x, y): the centre of Aula's cell; None until chosen.
def getTargetPose():
    grid = _grid("GUI.getTargetPose()")
    cell = grid.getDestiny()
    if cell[0] < 0 or cell[1] < 0:
        return None
    return grid.gridToWorld(int(cell[0]), int(cell[1]))


def _xy(pose, what):
    try:
        return float(pose[0]), float(pose[1])
    except (TypeError, IndexError, ValueError):
        raise TypeError(f"{what}: give a world point (x, y) in metres, got {pose!r}") from None


def _clip(cell):
    return min(max(int(cell), 0), RA_MAP_PX)  # RoboticsAcademy's clip: 0..400


# World (x, y) in metres -> (column, row) of the map: ((y + 250) * 400 / 500, (x + 250) * 400 / 500).
def worldToGrid(pose):
    x, y = _xy(pose, "GUI.worldToGrid()")
    return (_clip((y + RA_WORLD_M / 2) / RA_CELL_M), _clip((x + RA_WORLD_M / 2) / RA_CELL_M))


# (column, row) of the map -> world (x, y) in metres: (row * 500 / 400 - 250, column * 500 / 400 - 250).
def gridToWorld(cell):
    column, row = int(cell[0]), int(cell[1])
    return (row * RA_CELL_M - RA_WORLD_M / 2, column * RA_CELL_M - RA_WORLD_M / 2)


# Deprecated in RoboticsAcademy (worldToGrid as a list), kept as there.
def rowColumn(pose):
    return list(worldToGrid(pose))


# Draws the path on the map: a list of cells (column, row), as worldToGrid gives them; each is
# drawn in Aula's window at its world point.
def showPath(array):
    grid = _grid("GUI.showPath()")
    grid.resetPath()
    width, height = grid.getWidth(), grid.getHeight()
    for cell in array:
        x_m, y_m = gridToWorld(cell)
        column, row = grid.worldToGrid(x_m + RA_CELL_M / 2, y_m + RA_CELL_M / 2)  # the cell's centre
        if 0 <= column < width and 0 <= row < height:
            grid.setPathVal(column, row, 1.0)
    grid.setPathFinded()


# Shows a 400 x 400 numpy image [row, column] (your field, say, as getMap's cells) in the "Grid
# Field" window: each of Aula's cells takes the value of the picture's cell at its world point,
# drawn dark to light, as api.grid.field().
def showNumpy(image):
    grid = _grid("GUI.showNumpy()")
    image = _np.asarray(image, dtype=_np.float32)
    if image.shape[:2] != (RA_MAP_PX, RA_MAP_PX):
        raise ValueError(f"GUI.showNumpy(): an image of {image.shape[0]} x {image.shape[1] if image.ndim > 1 else 1},"
                         f" the map is {RA_MAP_PX} x {RA_MAP_PX} (rows x columns, as GUI.getMap())")
    if image.ndim == 3:  # a colour picture: its brightness
        image = image.mean(axis=2)
    field = grid.field()
    rows, columns = _np.indices(field.shape)
    x_m = _np.empty(field.shape)
    y_m = _np.empty(field.shape)
    x0, y0 = grid.gridToWorld(0, 0)
    x1, y1 = grid.gridToWorld(1, 1)
    x_m[:, :] = x0 + columns * (x1 - x0)  # Aula's cell centres
    y_m[:, :] = y0 + rows * (y1 - y0)
    ra_rows = _np.floor((x_m + RA_WORLD_M / 2) / RA_CELL_M).astype(_np.int64)
    ra_columns = _np.floor((y_m + RA_WORLD_M / 2) / RA_CELL_M).astype(_np.int64)
    inside = (ra_rows >= 0) & (ra_columns >= 0) & (ra_rows < RA_MAP_PX) & (ra_columns < RA_MAP_PX)
    field[:, :] = 0
    field[inside] = image[ra_rows[inside], ra_columns[inside]]
    grid.showGrid()


def __getattr__(name):
    _ra.missing("GUI", name, "getMap(url), getTargetPose(), worldToGrid((x, y)), gridToWorld((column, row)), "
                "rowColumn(pose), showPath(cells), showNumpy(image)")
