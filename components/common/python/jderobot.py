# JdeRobot-Academy 2017-18's `import jderobot` (the ICE interfaces' module): the data types its
# devices return (aula_academy.py). Aula hands MyAlgorithm its devices itself: nothing to connect.
from aula_academy import BumperData, LaserData, Pose3DData  # noqa: F401


def __getattr__(name):
    raise AttributeError(f"jderobot.{name}: Aula's jderobot has the data types LaserData, Pose3DData and BumperData; "
                         "the devices are MyAlgorithm's constructor's arguments")
