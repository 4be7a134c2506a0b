# =============================================================================================
#  TeleTaxi: YOUR Gradient Path Planning goes here.
#
#  generatePath(api) runs once when you press "Generate Path" (headless: at start-up once the
#  destination and the taxi's position are known). Fill api.grid with your field:
#      api.grid.getDestiny()  -> (x, y) cell of the destination      (x = column, y = row)
#      api.grid.getPose()     -> (x, y) cell of the taxi
#      api.grid.getMap()      -> the city map, a numpy uint8 array [y, x]: 0 obstacle, 255 free
#      api.grid.setVal(x, y, v) / getVal(x, y)       your field (floats, all 0 at first)
#      api.grid.field()       -> the same field as a numpy float32 array [y, x], writable
#      api.grid.setPathVal(x, y, v) / getPathVal(x, y)  mark the path cells (non-zero)
#      api.grid.setPathFinded()   the GUI then draws your path in green
#      api.grid.showGrid()        opens the "Grid Field" window
#      api.grid.gridToWorld(x, y) / worldToGrid(x_m, y_m)
#  (getMap() and field() share the C++ grid's memory: no copy.)
#
#  execute(api) runs every control period (80 ms of simulated time) after "GO!":
#      api.sensor.getRobotX(), getRobotY(), getRobotTheta()   metres, radians
#      api.vel.setV(v_mps), api.vel.setW(w_radps)             clamped to MaxV / MaxW
#
#  The same API as MyAlgorithm.cpp, under the same names (aula_teletaxi.pyi, for your editor).
#  Aula's Python has Debian's standard library, numpy and cv2.
#  Time is the simulator's: time.time(), time.sleep() and datetime.now() are sim time (as
#  api.time_s()), and time.perf_counter(); aula_profile.perf_counter() is real. A program of
#  RoboticsAcademy (import HAL...) or JdeRobot-Academy runs here too: docs/exercises/from-roboticsacademy.md.
#  Until you write something, this template keeps the taxi still.
# =============================================================================================
from aula_teletaxi import TaxiApi


class MyAlgorithm:
    def __init__(self, seed: int) -> None:
        self.seed = seed

    def generatePath(self, api: TaxiApi) -> None:
        # TODO: fill the field from the destination, then mark the path.
        pass

    def execute(self, api: TaxiApi) -> None:
        # TODO: follow your path. Meanwhile: stay still.
        api.vel.setV(0.0)
        api.vel.setW(0.0)
