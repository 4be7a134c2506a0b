# The Python host's own code (python_host.cpp runs it once, in the interpreter it starts): the
# student's file loaded afresh, run on a greenlet of the thread that calls it, on the
# simulator's clock, and a fault said in the student's lines.
#
# Every generation of the course's program runs unchanged; its shape is told from the file itself
# (docs/exercises/from-roboticsacademy.md):
# - a class: the file defines `class MyAlgorithm`, or imports or assigns the name (a hand-in of
#   several files: `from cleaner import Cleaner as MyAlgorithm`). Its constructor tells which:
#   - Aula's: MyAlgorithm(seed), made once when the file is chosen; execute(api) (TeleTaxi:
#     generatePath(api) too) is called every control period;
#   - JdeRobot-Academy 2017-18's: MyAlgorithm(pose3d, motors, laser, bumper) (the exercise's
#     devices, academy_devices.py: ORDER), usually a threading.Thread. Made at the first call with
#     the devices of the original's shapes (aula_academy.py), then driven as the original component
#     did: its own run() loop (execute() every time_cycle ms, in sim time) on the greenlet, never a
#     thread of its own; TeleTaxi's generatePath() (or what it connected to getPathSig) at "Generate
#     Path".
# - a program: any other file, run from its top (RoboticsAcademy 2021-23 `from HAL import HAL`,
#   2024 `import HAL, GUI`, 2025 `import HAL, WebGUI, Frequency`). It starts at the first call;
#   each call runs it on until it waits for the simulator (below), and the call then returns. A
#   program that ends in its first call without ever waiting (no class, no loop) is a fault that
#   says so.
#
# Every call runs the student's code on a greenlet of the calling thread (the one the execute
# budgets measure): waiting switches back to the caller, so the call returns, and the next call
# switches back in. The program waits for the next control period when it
# - calls time.sleep(d): as many periods as d covers (sim time), at least one (Frequency.tick(),
#   the same for what is left of its period);
# - reads a HAL sensor it has already read in this period (a loop that reads the HAL and never
#   sleeps: one pass per period; RoboticsAcademy's shape only);
# - starts another pass of a top-level `while True:` loop in the same period (RoboticsAcademy
#   2021-23 ran the loop's body once a period);
# - reads the clock (time.time(), perf_counter(), monotonic(), datetime.now()...) again at a
#   place of its code (the same line, called from the same lines) that read it at this sim time
#   already: a loop that waits on the clock costs what a time.sleep does. Reads made by other
#   modules (logging's timestamps...) wait only at the CLOCK_READS_PER_PERIOD-th in one period.
# A call of Aula's shape that waits is resumed, not called again, at the next periods.
#
# The clock: time.time(), time.perf_counter(), time.monotonic() (each with its _ns form),
# time.sleep(), time.gmtime()/localtime()/ctime()/strftime() without a time,
# datetime.datetime.now()/utcnow()/today()/fromtimestamp() and datetime.date.today() are the
# simulator's: seconds since the simulation started (the epoch, 1970-01-01 00:00:00 UTC, is the
# simulation's start), the same on every machine. time.process_time() and thread_time() (CPU
# time) stay real; aula_profile.perf_counter() is the real perf_counter, for profiling.
import datetime as _datetime
import os, sys, time, traceback, types

import greenlet

CLOCK_READS_PER_PERIOD = 1000

class ExecuteBudgetExceeded(BaseException):
    """Raised inside a call that overran Component.ExecuteBudget. Not an Exception, so that the
    student's own `except Exception:` does not swallow it."""

budget_text = ""

class NotAnAlgorithm(Exception):
    """What Aula cannot run the file as (said as it is, after the file's name)."""

# --- the simulator's clock -------------------------------------------------------------------

_real = types.SimpleNamespace(sleep=time.sleep, datetime=_datetime.datetime, date=_datetime.date,
                              perf_counter=time.perf_counter, perf_counter_ns=time.perf_counter_ns)
_now_us = 0          # sim time of the control period now running, microseconds
_runner = None       # the Runner whose call is running (None between calls)

_HOST_FILE = "<aula:host.py>"  # this file's name in tracebacks (python_host.cpp compiles it so)

def now_us():
    return _now_us

def _clock_read():
    if _runner is not None:
        _runner.clock_read()
    return _now_us

def _time():
    return _clock_read() / 1e6

def _time_ns():
    return _clock_read() * 1000

def _sleep(seconds):
    seconds = float(seconds)
    if seconds != seconds or seconds < 0:
        raise ValueError("sleep length must be non-negative")
    runner = _runner
    if runner is None or greenlet.getcurrent() is not runner.program or runner.forked():
        # Another thread, no program running, or a child the program forked: there is no sim time
        # to wait on here (a child must never switch back into the component's code).
        _real.sleep(seconds)
        return
    runner.sleep_us(round(seconds * 1e6))

def _struct(t):
    return time.gmtime(_time()) if t is None else t

_gmtime, _asctime, _strftime = time.gmtime, time.asctime, time.strftime

class _SimDatetime(_real.datetime):
    """datetime.datetime whose now()/utcnow()/today() read the simulator's clock."""
    @classmethod
    def now(cls, tz=None):
        moment = _real.datetime(1970, 1, 1) + _datetime.timedelta(microseconds=_clock_read())
        if tz is None:
            return cls._of(moment)
        return cls._of(moment.replace(tzinfo=_datetime.timezone.utc).astimezone(tz))
    @classmethod
    def utcnow(cls):
        return cls.now()
    @classmethod
    def today(cls):
        return cls.now()
    @classmethod
    def fromtimestamp(cls, t, tz=None):
        # No time zone: a sim time read back as the same date and time on every machine.
        if tz is None:
            return cls._of(_real.datetime(1970, 1, 1) + _datetime.timedelta(seconds=t))
        return cls._of(_real.datetime.fromtimestamp(t, tz))
    @classmethod
    def _of(cls, d):
        return cls(d.year, d.month, d.day, d.hour, d.minute, d.second, d.microsecond, d.tzinfo, fold=d.fold)

class _SimDate(_real.date):
    """datetime.date whose today() reads the simulator's clock."""
    @classmethod
    def today(cls):
        d = _SimDatetime.now()
        return cls(d.year, d.month, d.day)

def install_clock():
    time.time, time.time_ns = _time, _time_ns
    time.monotonic, time.monotonic_ns = _time, _time_ns
    time.perf_counter, time.perf_counter_ns = _time, _time_ns
    time.sleep = _sleep
    time.gmtime = lambda t=None: _gmtime(_time() if t is None else t)
    time.localtime = time.gmtime  # no time zone: the same on every machine
    time.ctime = lambda t=None: _asctime(time.gmtime(t))
    time.asctime = lambda t=None: _asctime(_struct(t))
    time.strftime = lambda fmt, t=None: _strftime(fmt, _struct(t))
    _datetime.datetime = _SimDatetime
    _datetime.date = _SimDate

# --- what the student prints -----------------------------------------------------------------

class ConsoleStream:
    """sys.stdout / sys.stderr: to the component's own stream as before, and to the window's
    console (python_host.cpp keeps the lines, capped)."""
    def __init__(self, stream, sink):
        self._stream, self._sink = stream, sink
    def write(self, text):
        text = str(text)
        self._sink(text)
        return self._stream.write(text)
    def flush(self):
        self._stream.flush()
    def __getattr__(self, name):
        return getattr(self._stream, name)

def install_console(sink):
    sys.stdout = ConsoleStream(sys.stdout, sink)
    sys.stderr = ConsoleStream(sys.stderr, sink)

# --- the student's file ----------------------------------------------------------------------

def _mine(filename, folder):
    # "<aula:HAL.py>", "<string>": never a file of the student's, whatever the working directory.
    return bool(filename) and not filename.startswith("<") and os.path.dirname(os.path.abspath(filename)) == folder

# Imported when the file is chosen, before any call (its first call, which runs the file's top, has
# the execute budget): the heavy modules of Aula's Python, when the file imports them (numpy always:
# the host seeds it). Nothing else: a module the file does not import costs it nothing.
PRELOADED = ("numpy", "cv2")

def preload(path):
    """Imports the PRELOADED modules the student's file imports (not one of the student's own)."""
    import ast
    try:
        with open(path, "rb") as f:
            tree = ast.parse(f.read(), path)
    except Exception:
        return  # the first call says what is wrong with the file
    folder = os.path.dirname(path)
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    for name in PRELOADED:
        shadowed = os.path.exists(os.path.join(folder, name + ".py")) or os.path.isdir(os.path.join(folder, name))
        if name == "numpy" or (name in names and not shadowed):  # numpy: the host seeds it
            try:
                __import__(name)
            except Exception:
                pass  # the student's import says it, in their line

def _names_algorithm_class(tree):
    """A class of either kind: `class MyAlgorithm`, or the name imported or assigned at the file's
    top (`from cleaner import Cleaner as MyAlgorithm`, `MyAlgorithm = Cleaner`)."""
    import ast
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == "MyAlgorithm":
            return True
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            if any((alias.asname or alias.name) == "MyAlgorithm" for alias in node.names):
                return True
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if any(isinstance(t, ast.Name) and t.id == "MyAlgorithm" for t in targets):
                return True
    return False

def _pace_top_level_loops(tree):
    """RoboticsAcademy 2021-23 ran the body of a program's `while True:` once a control period:
    each top-level `while True:` (or `while 1:`) pass starts with _aula_loop_pass(), which waits for
    the next period when no sim time has passed since the previous pass began."""
    import ast
    for node in tree.body:
        if isinstance(node, ast.While) and isinstance(node.test, ast.Constant) and node.test.value:
            first = node.body[0]
            call = ast.Expr(ast.Call(ast.Name("_aula_loop_pass", ast.Load()), [], []))
            node.body.insert(0, ast.copy_location(call, first))
    ast.fix_missing_locations(tree)

# The exercise's modules made fresh for every run and put in sys.modules at once (RoboticsAcademy's
# HAL and GUI, what they share); every other module Aula offers (MAP, WebGUI, Frequency, jderobot,
# sensors, colorama...) is a fallback, imported only when nothing else has the name: a student's
# own sensors.py, or Debian's python3-colorama, comes first.
DIRECT_MODULES = ("aula_ra", "aula_academy", "aula_profile", "HAL", "GUI", "academy_devices")
# RoboticsAcademy 2021-23 imported each as `from HAL import HAL`: the module is its own attribute.
SELF_NAMED = ("HAL", "GUI", "MAP", "WebGUI")

def _module(name, text):
    module = types.ModuleType(name)
    module.__file__ = f"<aula:{name}.py>"
    if name in SELF_NAMED:
        setattr(module, name, module)
    sys.modules[name] = module
    exec(compile(text, module.__file__, "exec", dont_inherit=True), module.__dict__)
    return module

class _Fallbacks:
    """A finder after every other (sys.meta_path's end): Aula's own modules by name."""
    def __init__(self):
        self.sources = {}
    def find_spec(self, name, path=None, target=None):
        import importlib.util
        if name not in self.sources:
            return None
        return importlib.util.spec_from_loader(name, self, origin=f"<aula:{name}.py>")
    def create_module(self, spec):
        return None
    def exec_module(self, module):
        name = module.__name__
        module.__file__ = f"<aula:{name}.py>"
        if name in SELF_NAMED:
            setattr(module, name, module)
        exec(compile(self.sources[name], module.__file__, "exec", dont_inherit=True), module.__dict__)

_fallbacks = _Fallbacks()
sys.meta_path.append(_fallbacks)

def _aula_module(module):
    return str(getattr(module, "__file__", None) or "").startswith("<aula:")

# The JdeRobot-Academy component's cycle when the file sets no time_cycle (ms).
ACADEMY_TIME_CYCLE_MS = 80

class Runner:
    """One run of the student's file: its module, its shape, and the greenlet that runs it."""

    def __init__(self, path, seed, modules):
        folder = os.path.dirname(path)
        self.folder = folder
        # The student's own modules are read afresh too (hot reload), and so are Aula's.
        for name, module in list(sys.modules.items()):
            if _mine(getattr(module, "__file__", None), folder) or (_aula_module(module) and name != "_aula_host"):
                del sys.modules[name]
        if folder in sys.path:
            sys.path.remove(folder)
        sys.path.insert(0, folder)
        with open(path, "rb") as f:
            source = f.read()
        import ast
        tree = compile(source, path, "exec", ast.PyCF_ONLY_AST, dont_inherit=True)
        self.is_program = not _names_algorithm_class(tree)
        if self.is_program:
            _pace_top_level_loops(tree)
        self.code = compile(tree, path, "exec", dont_inherit=True)
        import random, numpy
        random.seed(seed)
        numpy.random.seed(seed % 2**32)
        # default_rng() without a seed: the next generator of the run's seed sequence, not the OS's entropy.
        unseeded = getattr(numpy.random, "_aula_unseeded_default_rng", numpy.random.default_rng)
        numpy.random._aula_unseeded_default_rng = unseeded
        sequence = numpy.random.SeedSequence(seed)
        numpy.random.default_rng = lambda given=None: unseeded(sequence.spawn(1)[0] if given is None else given)
        # Aula's modules for this exercise, fresh for this run.
        _fallbacks.sources = {}
        for name, text in modules:
            if name in DIRECT_MODULES:
                _module(name, text)
            else:
                _fallbacks.sources[name] = text
        self.module = types.ModuleType("__main__")
        self.module.__file__ = path
        self.module._aula_loop_pass = self.loop_pass
        sys.modules["MyAlgorithm"] = self.module
        self.shape = "program" if self.is_program else None   # then "aula" or "academy"
        self.instance = None
        self.program = None          # the greenlet running the student's code, paused or running
        self.program_is_main = False # that greenlet runs the whole program (or the academy's run loop)
        self.caller = None           # the greenlet to switch back to when it waits
        self.finished = False        # a program (or an academy run loop) that ran to its end
        self.waited = False          # the program waited for the simulator at least once
        self.api = None
        self.read_this_period = set()
        self.clock_reads = 0
        self.clock_sites = set()     # where the program read the clock at this sim time
        self.clock_sites_us = None
        self.loop_pass_us = None     # sim time the last pass of a top-level loop began
        self._student_files = {}
        self.closing = False
        self.seed = seed
        self.pid = os.getpid()       # the component's process (a fork's child is not it)
        if not self.is_program:
            self._run_module()
            cls = self.module.__dict__.get("MyAlgorithm")
            if not isinstance(cls, type):
                raise NotAnAlgorithm("MyAlgorithm is not a class: define class MyAlgorithm with __init__(self, seed) "
                                     "and execute(self, api)")
            self.cls = cls
            self.academy = self._academy_arguments(cls)
            if self.academy is None:
                self.shape = "aula"
                self.instance = cls(seed)
            else:
                self.shape = "academy"   # made at the first call, where the devices can be read

    def _run_module(self):
        self.module.__name__ = "__main__" if self.is_program else "MyAlgorithm"
        exec(self.code, self.module.__dict__)

    def _academy_arguments(self, cls):
        """JdeRobot-Academy's constructor: the exercise's devices in the original's order (by their
        names when the parameters carry them), or None for Aula's MyAlgorithm(seed)."""
        import inspect
        order = tuple(getattr(sys.modules.get("academy_devices"), "ORDER", ()))
        try:
            parameters = [p for p in inspect.signature(cls).parameters.values()
                          if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        except (TypeError, ValueError):
            return None
        names = [p.name for p in parameters]
        if not order or len(names) < 2:
            return None
        if set(names) <= set(order):
            return names
        if len(names) == len(order):
            return list(order)
        required = [p.name for p in parameters if p.default is p.empty]
        raise NotAnAlgorithm(
            f"MyAlgorithm({', '.join(names)}): Aula makes MyAlgorithm(seed) (Aula's shape, execute(self, api)) "
            f"or, as JdeRobot-Academy did, MyAlgorithm({', '.join(order)}); this one needs {len(required)} arguments")

    def _make_academy(self):
        import academy_devices
        devices = academy_devices.devices()
        self.devices = devices
        self.instance = self.cls(*[devices[name] for name in self.academy])

    def _academy_plan(self):
        """TeleTaxi's "Generate Path": what the program connected to sensor.getPathSig, else its generatePath()."""
        if self.instance is None:
            self._make_academy()
        slots = getattr(getattr(self.devices.get("sensor"), "getPathSig", None), "slots", None)
        if slots:
            for slot in list(slots):
                slot()
        elif hasattr(self.instance, "generatePath"):
            self.instance.generatePath()

    def _academy_run(self):
        """The original component's play(): the class's own run() loop (a threading.Thread's, which
        calls execute() every time_cycle ms and sleeps the rest: sim time here), on this greenlet."""
        import threading
        if self.instance is None:
            self._make_academy()
        run = getattr(type(self.instance), "run", None)
        if callable(run) and run is not threading.Thread.run:
            self.instance.run()
            return
        home = sys.modules.get(type(self.instance).__module__)
        cycle_ms = float(getattr(home, "time_cycle", ACADEMY_TIME_CYCLE_MS))
        while True:
            self.instance.execute()
            time.sleep(cycle_ms / 1000.0)

    def _target(self, method, api):
        """What the greenlet of this call runs, and whether it is the whole program (None: nothing)."""
        if self.shape == "program":
            return (None if self.finished else self._run_module), True
        if self.shape == "academy":
            if method == "generatePath":
                return self._academy_plan, False
            return (None if self.finished else self._academy_run), True
        bound = getattr(self.instance, method)
        return (lambda: bound(api)), False

    # The host's one entry: runs the student's code for this control period, on a greenlet.
    def call(self, method, api, now):
        global _now_us, _runner
        _now_us = int(now)
        self.api = api
        self.read_this_period.clear()
        self.clock_reads = 0
        if self.program is None:
            target, main = self._target(method, api)
            if target is None:
                return
            self.program = greenlet.greenlet(target)
            self.program_is_main = main
        self.caller = greenlet.getcurrent()
        _runner = self
        try:
            self.program.switch()
        finally:
            _runner = None
            self.api = None
            ended = self.program is not None and self.program.dead
            if ended:
                self.program = None
                self.finished = self.finished or self.program_is_main
        if ended and self.shape == "program" and not self.waited:
            raise NotAnAlgorithm(self._why_nothing_ran())

    def _why_nothing_ran(self):
        hint = ""
        if callable(self.module.__dict__.get("execute")):
            hint = " It defines execute(): put it in class MyAlgorithm (def execute(self, api)) for Aula to call it."
        return ("the file ran to its end in its first call and never waited for the simulator: it has neither a class "
                "MyAlgorithm (Aula's shape: execute(self, api) every control period) nor a loop (RoboticsAcademy's "
                "shape: `while True:` with time.sleep() or Frequency.tick()), so nothing drove the robot: mark 0."
                + hint)

    def forked(self):
        """In a child process the program forked: its copy of the component must never run on."""
        return os.getpid() != self.pid

    def wait_period(self):
        """Back to the caller until the next control period (in a forked child: no wait at all)."""
        if self.forked():
            return
        if self.closing:
            raise greenlet.GreenletExit()
        self.waited = True
        self.caller.switch()
        if self.closing:
            raise greenlet.GreenletExit()

    def sleep_us(self, duration_us):
        until = _now_us + duration_us
        self.wait_period()
        while _now_us < until:
            self.wait_period()

    def sensor_read(self, name):
        if not self.is_program or greenlet.getcurrent() is not self.program:
            return
        if name in self.read_this_period:
            self.wait_period()
        self.read_this_period.add(name)

    def loop_pass(self):
        if greenlet.getcurrent() is not self.program:
            return
        if self.loop_pass_us == _now_us:
            self.wait_period()
        self.loop_pass_us = _now_us

    def _student_frame(self, frame):
        filename = frame.f_code.co_filename
        mine = self._student_files.get(filename)
        if mine is None:
            mine = self._student_files[filename] = _mine(filename, self.folder)
        return mine

    def clock_read(self):
        if greenlet.getcurrent() is not self.program:
            return
        # Who read it: the first frame outside this file. A module's read (logging's timestamps)
        # is not the program waiting on the clock, even when the program called that module.
        frame = sys._getframe(2)
        while frame is not None and frame.f_code.co_filename == _HOST_FILE:
            frame = frame.f_back
        # Where in the student's code the clock is read: its frames' code and instruction.
        site = []
        if frame is not None and self._student_frame(frame):
            while frame is not None:
                if self._student_frame(frame):
                    site.append((frame.f_code, frame.f_lasti))
                frame = frame.f_back
        if not site:
            self.clock_reads += 1
            if self.clock_reads >= CLOCK_READS_PER_PERIOD:
                self.wait_period()
            return
        site = tuple(site)
        if self.clock_sites_us != _now_us:
            self.clock_sites, self.clock_sites_us = set(), _now_us
        if site in self.clock_sites:
            self.wait_period()  # read here already, the clock unchanged since: a wait on the clock
            self.clock_sites, self.clock_sites_us = set(), _now_us
        self.clock_sites.add(site)

    def close(self):
        """Ends a paused program (GreenletExit inside it) when it can: on its own thread."""
        self.closing = True
        program, self.program = self.program, None
        if program is not None and not program.dead:
            try:
                program.throw(greenlet.GreenletExit())
            except BaseException:
                pass  # another thread's greenlet (greenlet ends it later there), or the program's last words

def current_api(what):
    """The exercise's API of the call now running, for HAL and GUI; `what` names the caller."""
    if _runner is None or _runner.api is None:
        raise RuntimeError(f"{what} can only be called from your program while it runs (in Aula its code runs "
                           "at each control period of the simulation)")
    return _runner.api

def sensor_read(name):
    """A HAL sensor read: a second read of the same sensor in one period waits for the next."""
    if _runner is not None:
        _runner.sensor_read(name)

# What a module the program imports and Aula's Python lacks is, on Debian (or what Aula offers instead).
MODULE_HINTS = {
    "pandas": "Debian's python3-pandas", "scipy": "Debian's python3-scipy", "sklearn": "Debian's python3-sklearn",
    "skimage": "Debian's python3-skimage", "networkx": "Debian's python3-networkx", "shapely": "Debian's python3-shapely",
    "PIL": "Debian's python3-pil", "yaml": "Debian's python3-yaml", "termcolor": "Debian's python3-termcolor",
    "colorama": "Debian's python3-colorama",
    "matplotlib": "Debian's python3-matplotlib; a run has no windows of its own: show an image with GUI.showNumpy "
                  "(TeleTaxi) or print what you need",
    "rclpy": "ROS 2, which Aula does not use: HAL and GUI give RoboticsAcademy's names without it",
    "rospy": "ROS 1, which Aula does not use: HAL and GUI give RoboticsAcademy's names without it",
    "comm": "JdeRobot's comm, which made the devices: Aula hands MyAlgorithm its devices itself",
    "config": "JdeRobot's config, read by the original's main program: Aula's settings are `aula run --KEY=VALUE`",
    "parallelIce": "JdeRobot's ICE clients: Aula hands MyAlgorithm its devices itself",
    "easyiceconfig": "JdeRobot's ICE configuration: Aula hands MyAlgorithm its devices itself",
}
# Aula's own modules a program may import (a name in other letters is a slip: `from hal import HAL`).
OFFERED_MODULES = ("HAL", "GUI", "MAP", "WebGUI", "Frequency", "jderobot", "sensors", "numpy", "cv2")

def _missing_module(name):
    top = (name or "").split(".")[0]
    for offered in OFFERED_MODULES:
        if top.lower() == offered.lower() and top != offered:
            return f"Aula's is `{offered}`, in these letters (`import {offered}`)"
    if top in MODULE_HINTS:
        return f"it is {MODULE_HINTS[top]}"
    if top in ("MAP", "sensors"):
        return f"{top} is TeleTaxi's (global navigation)"
    return ("Aula's Python has Debian's standard library, numpy, cv2, RoboticsAcademy's HAL, GUI, WebGUI and "
            f"Frequency, and JdeRobot-Academy's jderobot; Debian packages most modules as python3-{top.lower()}")

def _not_offered(exc):
    """`from HAL import getLaser`: Python's ImportError loses what HAL's __getattr__ said; say it again."""
    import re
    module = sys.modules.get(exc.name or "")
    found = re.match(r"cannot import name '([^']+)'", str(exc))
    if module is None or found is None or not _aula_module(module):
        return None
    try:
        getattr(module, found.group(1))
    except AttributeError as missing:
        return f"ImportError: {missing}"
    return None

def describe(exc, tb, path):
    folder = os.path.dirname(path)
    if isinstance(exc, SyntaxError) and _mine(exc.filename, folder):
        text = f"{os.path.basename(exc.filename)}:{exc.lineno}: {type(exc).__name__}: {exc.msg}"
        line = (exc.text or "").strip()
        text += f" (`{line}`)" if line else ""
        if "Missing parentheses in call to 'print'" in str(exc.msg):
            text += " (Python 2, as JdeRobot-Academy 2017-18 ran: Aula runs Python 3, where print is a function)"
        return text
    if isinstance(exc, ExecuteBudgetExceeded):
        what = budget_text + ": interrupted here"
    elif isinstance(exc, NotAnAlgorithm):
        what = str(exc)  # what Aula makes of the file, said in full
    elif isinstance(exc, ModuleNotFoundError):
        what = f"ModuleNotFoundError: no module named '{exc.name}' ({_missing_module(exc.name)})"
    elif isinstance(exc, ImportError) and _not_offered(exc):
        what = _not_offered(exc)
    else:
        message = str(exc)
        what = type(exc).__name__ + (": " + message if message else "")
    frames = [f for f in traceback.extract_tb(tb if tb is not None else exc.__traceback__) if _mine(f.filename, folder)]
    if not frames:
        return f"{os.path.basename(path)}: {what}"
    last = frames[-1]
    trail = "; ".join(f"{os.path.basename(f.filename)}:{f.lineno} in {f.name}: `{(f.line or '').strip()}`"
                      for f in frames[-3:])
    return f"{os.path.basename(last.filename)}:{last.lineno}: {what} (traceback, most recent call last: {trail})"
