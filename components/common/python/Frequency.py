# RoboticsAcademy 2025's Frequency, on the simulator's clock: `import Frequency` and
# `Frequency.tick()` at the end of a loop's body. tick(ideal_rate) waits what is left of the
# rate's period since the previous tick (sim time), as a time.sleep of it: at least one control
# period when the loop's pass has not waited otherwise (host.py).
import time

import _aula_host as _host

_last_tick_us = None  # sim time of the previous tick (this run's module is fresh)


def tick(ideal_rate=50):
    """Paces the loop at `ideal_rate` Hz (50 by default, as RoboticsAcademy's)."""
    global _last_tick_us
    rate_hz = float(ideal_rate)
    if not rate_hz > 0 or rate_hz == float("inf"):
        raise ValueError(f"Frequency.tick({ideal_rate!r}): the rate is in Hz, a number above 0")
    period_us = 1e6 / rate_hz
    now_us = _host.now_us()
    if _last_tick_us is None or now_us - _last_tick_us < period_us:
        # The pass took less than its period: sleep the rest (sleep waits one control period at least).
        left_us = period_us if _last_tick_us is None else period_us - (now_us - _last_tick_us)
        time.sleep(left_us / 1e6)
    _last_tick_us = _host.now_us()


def __getattr__(name):
    raise AttributeError(f"Frequency.{name}: Aula's Frequency has tick(ideal_rate=50) only")
