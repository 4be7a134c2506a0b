# sendV(NaN) on every call: refused (the axis set to 0) and counted, as for C++.
class MyAlgorithm:
    def __init__(self, seed):
        pass

    def execute(self, api):
        api.motors.sendV(float("nan"))
        api.motors.sendW(0.0)
