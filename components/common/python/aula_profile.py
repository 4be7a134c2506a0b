# The real clock, for profiling a program whose clocks are all the simulator's (host.py):
# `import aula_profile; t0 = aula_profile.perf_counter()`. Real seconds of this computer: never
# for timing what the robot does (the mark is on sim time).
import _aula_host as _host

perf_counter = _host._real.perf_counter
perf_counter_ns = _host._real.perf_counter_ns
