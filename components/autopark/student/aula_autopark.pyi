# Autopark's API (aula/autopark/autopark_algorithm.hpp) as MyAlgorithm.py sees it: stubs for
# your editor (with aula_devices.pyi beside it).
from typing import Callable

from aula_devices import Bumper as Bumper
from aula_devices import BumperData as BumperData
from aula_devices import Laser as Laser
from aula_devices import LaserData as LaserData
from aula_devices import Motors as Motors
from aula_devices import Pose3d as Pose3d

class LaserMount:
    # Where a laser sits on the car: body frame (x forward, y left), metres and radians.
    x_m: float
    y_m: float
    yaw_rad: float

# Calls echo(x_m, y_m) with the world position of every beam of `scan` that hit something, for
# a laser at `mount` on a car at (x, y, yaw).
def forEachEcho(car_x_m: float, car_y_m: float, car_yaw_rad: float, mount: LaserMount, scan: LaserData,
                echo: Callable[[float, float], None]) -> None: ...

class AutoparkApi:
    @property
    def pose3d(self) -> Pose3d: ...  # getX(), getY(), getYaw(): the car's centre, metres, radians
    @property
    def laser1(self) -> Laser: ...  # front: 180 beams over -90..90 degrees, metres and mm
    @property
    def laser2(self) -> Laser: ...  # rear
    @property
    def laser3(self) -> Laser: ...  # right
    @property
    def motors(self) -> Motors: ...  # sendV(), sendW(), clamped to MaxV / MaxW
    period_s: float  # sim seconds between execute() calls
    mount1: LaserMount  # the lasers' mounting poses (from the world)
    mount2: LaserMount
    mount3: LaserMount
    car_length_m: float
    car_width_m: float
    # Turning radius the car needs: 0 for a car that turns in place, else |w| <= |v| / R.
    min_turn_radius_m: float
    # Body-frame x of the point the car turns about (0: its centre; a car-like car's rear axle).
    turn_centre_x_m: float
    wheelbase_m: float
    # What your algorithm says about where it stands: the window shows it under the car's numbers.
    status: str
    # Sim time of this control period, seconds since the simulation started (= time.time()).
    def time_s(self) -> float: ...
