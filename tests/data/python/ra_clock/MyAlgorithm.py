# The clock and the pacing of a program in RoboticsAcademy's shape (vacuum, Period 0.08 s),
# Frequency.tick() included:
# each check raises AssertionError with what it saw; all passed, it prints "CLOCK OK" and drives.
import GUI
import HAL
import logging
import math
import time
import datetime
import aula_profile
import Frequency
from datetime import datetime as dt

PERIOD = 0.08
log = logging.getLogger("ra_clock")
log.setLevel(logging.INFO)
log.addHandler(logging.NullHandler())
log.propagate = False


def check(condition, what):
    if not condition:
        raise AssertionError(what)


t0 = time.time()
check(time.monotonic() == t0 and time.time_ns() == round(t0 * 1e9), "monotonic/time_ns are not time.time()")
pose = HAL.getPose3d()
check(abs(pose.timeStamp - t0) < 1e-9, f"the pose's timeStamp {pose.timeStamp} is not {t0}")
time.sleep(0.03)                      # shorter than a period: one period
t1 = time.time()
check(abs(t1 - t0 - PERIOD) < 1e-9, f"sleep(0.03) took {t1 - t0} s of sim time")
time.sleep(1.0)                       # as many periods as it covers
t2 = time.time()
check(1.0 - 1e-9 <= t2 - t1 < 1.0 + PERIOD, f"sleep(1.0) took {t2 - t1} s")
HAL.getLaserData()                    # a loop that reads the HAL and never sleeps: one pass per period
ta = time.time()
HAL.getLaserData()
check(abs(time.time() - ta - PERIOD) < 1e-9, f"a second laser read in one period took {time.time() - ta} s")
t3 = time.time()
while time.time() - t3 < 0.5:         # waiting on the clock ends
    pass
check(0.5 - 1e-9 <= time.time() - t3 < 0.5 + PERIOD, f"a busy wait of 0.5 s took {time.time() - t3} s")
now = datetime.datetime.now()
check(abs((now - datetime.datetime(1970, 1, 1)).total_seconds() - time.time()) < 1e-6, f"datetime.now() is {now}")
check(dt.now() == now and datetime.date.today() == datetime.date(1970, 1, 1), "from datetime import datetime")
check(dt.fromtimestamp(time.time()) == now, f"datetime.fromtimestamp(time.time()) is {dt.fromtimestamp(time.time())}")
p0, t4 = time.perf_counter(), time.time()
check(p0 == t4 and time.perf_counter_ns() == round(t4 * 1e9), "perf_counter is not sim time")
r0 = aula_profile.perf_counter()
sum(range(200000))
check(aula_profile.perf_counter() > r0 and time.time() == t4, "aula_profile.perf_counter is not real, or time.time() moved")
t7 = time.time()
for beam in range(5):
    log.info("beam %d", beam)         # logging reads the clock: not the program waiting on it
check(time.time() == t7, f"five log lines took {time.time() - t7} s")
for _ in range(3):
    last = time.time()                # read here again, the clock unchanged: a period each time
check(abs(last - t7 - 2 * PERIOD) < 1e-9, f"three reads at one place took {last - t7} s")
t5 = time.time()
Frequency.tick(2)                     # the first tick: the rate's period (0.5 s) of sim time
Frequency.tick(2)                     # the next: 0.5 s after the first ended
check(1.0 - 1e-9 <= time.time() - t5 < 1.0 + 2 * PERIOD, f"two ticks at 2 Hz took {time.time() - t5} s")
time.sleep(0.6)
t6 = time.time()
Frequency.tick(2)                     # the pass took longer than its period: no wait
check(time.time() == t6, f"a tick after a long pass waited {time.time() - t6} s")
from HAL import HAL as RoboticsAcademy2021
check(RoboticsAcademy2021 is HAL, "from HAL import HAL is not the HAL module")
laser = HAL.getLaserData()
check(isinstance(laser.values, list) and len(laser.values) == 180, "the laser's values are not a list of 180")
check(abs(laser.minAngle) < 1e-6 and abs(laser.maxAngle - math.pi) < 1e-6, f"angles {laser.minAngle}..{laser.maxAngle}")
check((HAL.RIGHT_BUMPER, HAL.CENTER_BUMPER, HAL.LEFT_BUMPER) == (0, 1, 2), "RoboticsAcademy's bumper numbers")
check(HAL.getBumperData().bumper in (0, 1, 2), "bumper side")
print(f"CLOCK OK at {time.time():.2f} s")
while True:
    HAL.setV(0.2)
    HAL.setW(0.3)
    time.sleep(0.1)
