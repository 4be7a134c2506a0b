# RoboticsAcademy's own files were hal.py and gui.py; a program imports Aula's HAL (line 2).
from hal import HAL

while True:
    HAL.setV(0.1)
