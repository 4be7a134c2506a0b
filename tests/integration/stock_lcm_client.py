"""An independent LCM client on a run's URL: python-lcm, with the project's own types (lcm-gen -p).

Listens to every channel (".*") until the run is over, decodes each message with the type whose
fingerprint it carries, and prints one line per channel: CHANNEL TYPE COUNT. A message that no
project type decodes is an error (exit 1).

The run is over when STOP_FILE appears (the test writes it once `aula run` has exited) holding the
number of poses the referee graded: the client then reads what is still queued until it has seen
that many ROOMBA_POSE messages, or until nothing more has come for 10 s (a lost message: the test
fails on the count). No silence while the run is under way ends it: a run stalled by a loaded
machine is still the run.
Usage: python3 stock_lcm_client.py URL TYPES_DIR READY_FILE STOP_FILE
"""
import importlib
import os
import pkgutil
import sys
import time

import lcm

url, types_dir, ready_file, stop_file = sys.argv[1:5]
sys.path.insert(0, types_dir)
import aula  # noqa: E402  (the generated package)

types = {}
for module in pkgutil.iter_modules(aula.__path__):
    cls = getattr(importlib.import_module("aula." + module.name), module.name)
    types[cls._get_packed_fingerprint()] = cls

counts = {}
undecodable = []


def on_message(channel, data):
    if channel == "LCM_SELF_TEST":  # LCM's own, sent by every LCM instance as it starts receiving
        return
    cls = types.get(data[:8])
    if cls is None:
        undecodable.append(channel)
        return
    cls.decode(data)  # raises on a malformed message
    key = (channel, cls.__name__)
    counts[key] = counts.get(key, 0) + 1


bus = lcm.LCM(url)
bus.subscribe(".*", on_message)
open(ready_file, "w").close()
last = time.monotonic()
while True:
    if bus.handle_timeout(100) > 0:
        last = time.monotonic()
    elif os.path.exists(stop_file):
        with open(stop_file) as f:
            graded = int(f.read())
        if counts.get(("ROOMBA_POSE", "pose3d_t"), 0) >= graded or time.monotonic() - last > 10.0:
            break
for (channel, name), count in sorted(counts.items()):
    print(channel, name, count)
if undecodable:
    print("undecodable:", sorted(set(undecodable)), file=sys.stderr)
    sys.exit(1)
