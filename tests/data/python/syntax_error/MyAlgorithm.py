# A student's file with a syntax error on line 7: the component must say where, and stay up.
class MyAlgorithm:
    def __init__(self, seed):
        self.calls = 0

    def execute(self, api):
        if self.calls = 3:
            api.motors.sendV(0.3)
