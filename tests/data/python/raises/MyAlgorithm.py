# Drives, then on its 31st call divides by zero two calls deep (line 8), called from line 18.
class MyAlgorithm:
    def __init__(self, seed):
        self.calls = 0

    def speed(self, api):
        remaining = 30 - self.calls
        return 1.0 / remaining

    def execute(self, api):
        self.calls += 1
        if self.calls <= 30:
            api.motors.sendV(0.3)
            api.motors.sendW(0.0)
            return
        # The 31st call: one step too far.
        self.calls -= 1
        api.motors.sendV(self.speed(api))
