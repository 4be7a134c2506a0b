# The student's own base class, beside MyAlgorithm.py: a widening spiral that turns away for
# 15 calls when the bumper is pressed, Aula's shape.
class Cleaner:
    def __init__(self, seed):
        self.calls = 0
        self.turning = 0

    def execute(self, api):
        self.calls += 1
        if api.bumper.getBumperData().state == 1:
            self.turning = 15
        if self.turning > 0:
            self.turning -= 1
            api.motors.sendV(-0.05)
            api.motors.sendW(1.0)
        else:
            api.motors.sendV(0.25)
            api.motors.sendW(1.0 / (1.0 + 0.02 * self.calls))
