# Drives, then loops for ever on its 6th call (lines 11-12). `except Exception` must not swallow
# the budget's interrupt.
class MyAlgorithm:
    def __init__(self, seed):
        self.calls = 0

    def execute(self, api):
        self.calls += 1
        n = 0
        try:
            while self.calls > 5:
                n += 1
        except Exception:
            pass
        api.motors.sendV(0.3)
