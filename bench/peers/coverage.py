"""Coverage counted as Aula's vacuum referee counts it (libs/world/src/occupancy_map.cpp,
libs/scoring/src/coverage_grid.cpp): the static geometry in the height band rasterised on a grid
fitted to its bounds (a cell is an obstacle when its centre is inside a footprint), the floor the
free cells 4-connected to the robot's start, and at every pose sample the robot's footprint disc
marks the floor cells whose centres it holds."""
import math
from collections import deque
from dataclasses import dataclass

import numpy as np

from aula_world import fail


@dataclass
class Grid:
    resolution_m: float
    origin_x_m: float  # world x of column 0's left edge
    origin_y_m: float  # world y of row 0's top edge (rows grow with -y)
    width_px: int
    height_px: int

    def col_of(self, x_m):
        return math.floor((x_m - self.origin_x_m) / self.resolution_m)

    def row_of(self, y_m):
        return math.floor((self.origin_y_m - y_m) / self.resolution_m)

    def centres_x_m(self, col0, col1):
        return self.origin_x_m + (np.arange(col0, col1 + 1) + 0.5) * self.resolution_m

    def centres_y_m(self, row0, row1):
        return self.origin_y_m - (np.arange(row0, row1 + 1) + 0.5) * self.resolution_m


def half_extents_m(p):
    if p.kind == "cylinder":
        return p.radius_m, p.radius_m
    c, s = abs(math.cos(p.yaw_rad())), abs(math.sin(p.yaw_rad()))
    hl, hw = p.size_m[0] / 2, p.size_m[1] / 2
    return c * hl + s * hw, s * hl + c * hw


def fit_grid(statics, resolution_m):
    lo_x = lo_y = math.inf
    hi_x = hi_y = -math.inf
    for p in statics:
        hx, hy = half_extents_m(p)
        x, y = p.pose[0, 3], p.pose[1, 3]
        lo_x, lo_y, hi_x, hi_y = min(lo_x, x - hx), min(lo_y, y - hy), max(hi_x, x + hx), max(hi_y, y + hy)
    width = math.ceil((hi_x - lo_x) / resolution_m - 1e-6)
    height = math.ceil((hi_y - lo_y) / resolution_m - 1e-6)
    cx, cy = (lo_x + hi_x) / 2, (lo_y + hi_y) / 2
    return Grid(resolution_m, cx - width * resolution_m / 2, cy + height * resolution_m / 2, width, height)


def mark_obstacle(free, grid, p):
    x, y = p.pose[0, 3], p.pose[1, 3]
    reach = p.radius_m if p.kind == "cylinder" else 0.5 * math.hypot(p.size_m[0], p.size_m[1])
    col0, col1 = max(0, grid.col_of(x - reach)), min(grid.width_px - 1, grid.col_of(x + reach))
    row0, row1 = max(0, grid.row_of(y + reach)), min(grid.height_px - 1, grid.row_of(y - reach))
    if col0 > col1 or row0 > row1:
        return
    dx = grid.centres_x_m(col0, col1)[None, :] - x
    dy = grid.centres_y_m(row0, row1)[:, None] - y
    if p.kind == "cylinder":
        inside = dx * dx + dy * dy <= p.radius_m * p.radius_m
    else:
        c, s = math.cos(p.yaw_rad()), math.sin(p.yaw_rad())
        inside = (np.abs(c * dx + s * dy) <= p.size_m[0] / 2) & (np.abs(-s * dx + c * dy) <= p.size_m[1] / 2)
    free[row0:row1 + 1, col0:col1 + 1] &= ~inside


def free_cells(statics, grid, z_band_m):
    free = np.ones((grid.height_px, grid.width_px), dtype=bool)
    for p in statics:
        z0, z1 = p.z_range_m()
        if not (z1 < z_band_m[0] or z0 > z_band_m[1]):
            mark_obstacle(free, grid, p)
    return free


def row_runs(free_row):
    """The free runs of one row as (first col, last col) pairs."""
    edges = np.diff(np.concatenate(([0], free_row.astype(np.int8), [0])))
    return list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1))


def reachable_floor(free, start_row, start_col):
    """The free cells 4-connected to the start, filled run by run."""
    runs = [row_runs(free[row]) for row in range(free.shape[0])]
    floor = np.zeros_like(free)
    start = next(((a, b) for a, b in runs[start_row] if a <= start_col <= b), None)
    if start is None:
        fail("coverage: the robot's start is not on the floor")
    queue, seen = deque([(start_row, start)]), {(start_row, start)}
    while queue:
        row, (a, b) = queue.popleft()
        floor[row, a:b + 1] = True
        for near in (row - 1, row + 1):
            if 0 <= near < free.shape[0]:
                for run in runs[near]:
                    if run[0] <= b and a <= run[1] and (near, run) not in seen:
                        seen.add((near, run))
                        queue.append((near, run))
    return floor


def cleaned_cells(poses_m, grid, radius_m, chunk=1024):
    """Every cell whose centre lies within radius_m of a pose sample (x, y)."""
    cleaned = np.zeros((grid.height_px, grid.width_px), dtype=bool)
    r_px = radius_m / grid.resolution_m
    span = np.arange(math.ceil(2 * r_px) + 2)
    for first in range(0, len(poses_m), chunk):
        xy = poses_m[first:first + chunk]
        cx = (xy[:, 0] - grid.origin_x_m) / grid.resolution_m
        cy = (grid.origin_y_m - xy[:, 1]) / grid.resolution_m
        cols = np.floor(cx - r_px).astype(int)[:, None, None] + span[None, None, :]
        rows = np.floor(cy - r_px).astype(int)[:, None, None] + span[None, :, None]
        dx, dy = cols + 0.5 - cx[:, None, None], rows + 0.5 - cy[:, None, None]
        on_grid = (cols >= 0) & (cols < grid.width_px) & (rows >= 0) & (rows < grid.height_px)
        hit = (dx * dx + dy * dy <= r_px * r_px) & on_grid
        cleaned[np.broadcast_to(rows, hit.shape)[hit], np.broadcast_to(cols, hit.shape)[hit]] = True
    return cleaned


def coverage(statics, start_xy_m, poses_m, resolution_m, z_band_m, radius_m):
    """(coverage %, floor area m^2) of the pose samples on the world's floor."""
    grid = fit_grid(statics, resolution_m)
    free = free_cells(statics, grid, z_band_m)
    floor = reachable_floor(free, grid.row_of(start_xy_m[1]), grid.col_of(start_xy_m[0]))
    cleaned = cleaned_cells(np.asarray(poses_m), grid, radius_m) & floor
    floor_px = int(floor.sum())
    return 100.0 * int(cleaned.sum()) / floor_px, floor_px * resolution_m ** 2
