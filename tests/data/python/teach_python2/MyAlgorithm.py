# A JdeRobot-Academy 2017-18 file in Python 2 (line 5): Aula runs Python 3.
import threading


print "Execute"
