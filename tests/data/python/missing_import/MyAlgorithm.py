# Imports a module that Aula's Python does not have (line 2).
import pandas


class MyAlgorithm:
    def __init__(self, seed):
        pass

    def execute(self, api):
        api.motors.sendV(0.3)
