# RoboticsAcademy 2021-23's shape: `from HAL import HAL`, `from GUI import GUI`, a `while True:`
# body with no time.sleep. Along the lane (heading held on 0) until 12 m on, slower when the front
# laser sees something near, then stops and stays.
from GUI import GUI
from HAL import HAL

start_x = None
while True:
    pose = HAL.getPose3d()
    front = HAL.getFrontLaserData()
    if start_x is None:
        start_x = pose.x
        print(f"start at x {pose.x:.2f} m, {len(front.values)} front beams")
    ahead = min(front.values[70:110])
    if pose.x - start_x < 12.0 and ahead > 1.5:
        HAL.setV(1.0 if ahead > 4.0 else 0.4)
        HAL.setW(-0.8 * pose.yaw - 0.2 * (pose.y - 2.5))
    else:
        HAL.setV(0.0)
        HAL.setW(0.0)
