# Dies at its import (line 4): run in every exercise, it must get mark 0 with the reason.
import HAL

SPEED = 1.0 / 0
while True:
    HAL.setV(SPEED)
