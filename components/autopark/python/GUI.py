# RoboticsAcademy's GUI for Autopark: it offers a student no function (its page draws the car,
# the lasers and the street by itself), and neither does Aula's: the component's window shows
# them and what the program prints. `import GUI` works, as in RoboticsAcademy.
import aula_ra as _ra


def __getattr__(name):
    _ra.missing("GUI", name, "nothing to call (the window draws the car, its lasers and the street)")
