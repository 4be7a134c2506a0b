# A module of the student's beside MyAlgorithm.py: Aula's shape under another name. Ahead until
# the bumper is pressed, then back and turn for 20 calls.
class Cleaner:
    def __init__(self, seed):
        self.away = 0
        print(f"Cleaner made with seed {seed}")

    def execute(self, api):
        if api.bumper.getBumperData().state == 1:
            self.away = 20
        self.away = max(0, self.away - 1)
        api.motors.sendV(-0.1 if self.away > 10 else (0.0 if self.away else 0.3))
        api.motors.sendW(0.9 if self.away else 0.0)
