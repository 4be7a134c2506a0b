# RoboticsAcademy's vacuum page offers HAL.getPose3d().x; Aula's vacuum is not told where it is.
import HAL
import time

while True:
    pose = HAL.getPose3d()
    if pose.x > 1.0:
        HAL.setV(0)
    time.sleep(0.1)
