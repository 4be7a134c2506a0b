# A hand-in of two files (issue 57): class MyAlgorithm subclasses the module beside it's class,
# and counts the calls it passes on.
from cleaner import Cleaner


class MyAlgorithm(Cleaner):
    def execute(self, api):
        super().execute(api)
        if self.calls == 100:
            print("MyAlgorithm(Cleaner): 100 calls")
