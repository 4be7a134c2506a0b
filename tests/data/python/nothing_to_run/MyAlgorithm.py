# Neither a class MyAlgorithm nor a loop: functions Aula never calls, and one command at the top.
import HAL


def execute():
    HAL.setV(0.3)


HAL.setW(0.1)
