# RoboticsAcademy's GUI for the vacuum cleaner: it offers a student no function (its page draws
# the robot and the map by itself), and neither does Aula's: the component's window shows the
# map, the cleaned area and what the program prints. `import GUI` works, as in RoboticsAcademy.
import aula_ra as _ra


def __getattr__(name):
    _ra.missing("GUI", name, "nothing to call (the window draws the robot, the map and the cleaned area)")
