# RoboticsAcademy 2025's shape: `import HAL`, `import WebGUI`, `import Frequency` and
# Frequency.tick() at the end of the loop's body; colorama for a coloured line. A wall follower:
# keeps the wall on its right about 0.4 m away, turns left when the front is near.
import Frequency
import HAL
import WebGUI
from colorama import Fore, Style

print(Fore.CYAN + "following walls" + Style.RESET_ALL)
while True:
    values = HAL.getLaserData().values
    front, right = min(values[75:105]), min(values[10:50])
    if front < 0.45 or HAL.getBumperData().state == 1:
        HAL.setV(0.0)
        HAL.setW(0.7)
    else:
        HAL.setV(0.25)
        HAL.setW(max(-0.6, min(0.6, 1.5 * (0.4 - right))))
    Frequency.tick(25)
