# Imports Autopark's laser in the vacuum (line 3): the error says what the vacuum's HAL has.
import time
from HAL import getFrontLaserData

while True:
    time.sleep(0.1)
