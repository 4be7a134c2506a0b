# The simulator's clock in Aula's own shape (vacuum, class MyAlgorithm): time.time() is
# api.time_s() at every call, a period apart; a time.sleep() inside execute() waits in sim time
# (the call goes on at a later period). Prints "EXECUTE CLOCK OK" after 20 calls.
import time


class MyAlgorithm:
    def __init__(self, seed):
        self.last = None
        self.calls = 0

    def execute(self, api):
        now = time.time()
        if now != api.time_s():
            raise AssertionError(f"time.time() {now} is not api.time_s() {api.time_s()}")
        if self.last is not None and abs(now - self.last - api.period_s) > 1e-9:
            raise AssertionError(f"{now - self.last} s between two calls")
        self.calls += 1
        if self.calls == 10:
            before = time.time()
            time.sleep(0.5)
            slept = time.time() - before
            if not 0.5 - 1e-9 <= slept < 0.5 + api.period_s:
                raise AssertionError(f"time.sleep(0.5) in execute() took {slept} s")
        self.last = time.time()
        if self.calls == 20:
            print("EXECUTE CLOCK OK")
        api.motors.sendV(0.1)
