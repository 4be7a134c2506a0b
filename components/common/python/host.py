# The Python host's own code (python_host.cpp runs it once, in the interpreter it starts): the
# student's file loaded afresh, run on a greenlet of the thread that calls it, on the
# simulator's clock, and a fault said in the student's lines.
#
# Two shapes of program, told apart by the file itself:
# - Aula's: a file that defines `class MyAlgorithm` is made once, MyAlgorithm(seed), and its
#   execute(api) (TeleTaxi: generatePath(api) too) is called every control period.
# - RoboticsAcademy's: any other file is a program run from its top (`import HAL`, top-level
#   code, `while True:`, `time.sleep`). It starts at the first call; each call runs it on until
#   it waits for the simulator (below), and the call then returns.
#
# Every call runs the student's code on a greenlet of the calling thread (the one the execute
# budgets measure): waiting switches back to the caller, so the call returns, and the next call
# switches back in. The program waits for the next control period when it
# - calls time.sleep(d): as many periods as d covers (sim time), at least one;
# - reads a HAL sensor it has already read in this period (a loop that reads the HAL and never
#   sleeps: one pass per period; RoboticsAcademy's shape only);
# - reads the clock (time.time(), monotonic(), datetime.now()...) for the
#   CLOCK_READS_PER_PERIOD-th time in one period (a loop that waits on the clock: sim time does
#   not pass while the program runs).
# A call of Aula's shape that waits is resumed, not called again, at the next periods.
#
# The clock: time.time(), time.time_ns(), time.monotonic(), time.monotonic_ns(), time.sleep(),
# time.gmtime()/localtime()/ctime()/strftime() without a time, datetime.datetime.now()/utcnow()/
# today()/fromtimestamp() and datetime.date.today() are the simulator's: seconds since the simulation started (the
# epoch, 1970-01-01 00:00:00 UTC, is the simulation's start), the same on every machine.
# time.perf_counter() and time.process_time() stay real, for profiling.
import datetime as _datetime
import os, sys, time, traceback, types

import greenlet

CLOCK_READS_PER_PERIOD = 1000

class ExecuteBudgetExceeded(BaseException):
    """Raised inside a call that overran Component.ExecuteBudget. Not an Exception, so that the
    student's own `except Exception:` does not swallow it."""

budget_text = ""

class NotAnAlgorithm(Exception):
    pass

# --- the simulator's clock -------------------------------------------------------------------

_real = types.SimpleNamespace(sleep=time.sleep, datetime=_datetime.datetime, date=_datetime.date)
_now_us = 0          # sim time of the control period now running, microseconds
_runner = None       # the Runner whose call is running (None between calls)

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
    return bool(filename) and os.path.dirname(os.path.abspath(filename)) == folder

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

def _defines_algorithm_class(tree):
    import ast
    return any(isinstance(node, ast.ClassDef) and node.name == "MyAlgorithm" for node in tree.body)

class Runner:
    """One run of the student's file: its module, its shape, and the greenlet that runs it."""

    def __init__(self, path, seed, modules):
        folder = os.path.dirname(path)
        # The student's own modules are read afresh too (hot reload).
        for name, module in list(sys.modules.items()):
            if _mine(getattr(module, "__file__", None), folder):
                del sys.modules[name]
        if folder in sys.path:
            sys.path.remove(folder)
        sys.path.insert(0, folder)
        with open(path, "rb") as f:
            source = f.read()
        import ast
        tree = compile(source, path, "exec", ast.PyCF_ONLY_AST, dont_inherit=True)
        self.code = compile(tree, path, "exec", dont_inherit=True)
        import random, numpy
        random.seed(seed)
        numpy.random.seed(seed % 2**32)
        # default_rng() without a seed: the next generator of the run's seed sequence, not the OS's entropy.
        unseeded = getattr(numpy.random, "_aula_unseeded_default_rng", numpy.random.default_rng)
        numpy.random._aula_unseeded_default_rng = unseeded
        sequence = numpy.random.SeedSequence(seed)
        numpy.random.default_rng = lambda given=None: unseeded(sequence.spawn(1)[0] if given is None else given)
        # RoboticsAcademy's HAL and GUI (and what they share), fresh for this run: the exercise's own.
        for name, text in modules:
            module = types.ModuleType(name)
            module.__file__ = f"<aula:{name}.py>"
            sys.modules[name] = module
            exec(compile(text, module.__file__, "exec", dont_inherit=True), module.__dict__)
        self.module = types.ModuleType("__main__")
        self.module.__file__ = path
        sys.modules["MyAlgorithm"] = self.module
        self.is_program = not _defines_algorithm_class(tree)
        self.instance = None
        self.program = None          # the greenlet running the student's code, paused or running
        self.caller = None           # the greenlet to switch back to when it waits
        self.finished = False        # a program that ran to its end
        self.api = None
        self.read_this_period = set()
        self.clock_reads = 0
        self.closing = False
        self.seed = seed
        self.pid = os.getpid()       # the component's process (a fork's child is not it)
        if not self.is_program:
            self._run_module()
            cls = self.module.__dict__.get("MyAlgorithm")
            if not isinstance(cls, type):
                raise NotAnAlgorithm("no class MyAlgorithm: define class MyAlgorithm with __init__(self, seed) "
                                     "and execute(self, api)")
            self.instance = cls(seed)

    def _run_module(self):
        self.module.__name__ = "__main__" if self.is_program else "MyAlgorithm"
        exec(self.code, self.module.__dict__)

    # The host's one entry: runs the student's code for this control period, on a greenlet.
    def call(self, method, api, now):
        global _now_us, _runner
        _now_us = int(now)
        self.api = api
        self.read_this_period.clear()
        self.clock_reads = 0
        if self.program is None:
            if self.is_program:
                if self.finished:
                    return
                self.program = greenlet.greenlet(self._run_module)
            else:
                bound = getattr(self.instance, method)
                self.program = greenlet.greenlet(lambda: bound(api))
        self.caller = greenlet.getcurrent()
        _runner = self
        try:
            self.program.switch()
        finally:
            _runner = None
            self.api = None
            if self.program is not None and self.program.dead:
                self.program = None
                self.finished = self.is_program

    def forked(self):
        """In a child process the program forked: its copy of the component must never run on."""
        return os.getpid() != self.pid

    def wait_period(self):
        """Back to the caller until the next control period (in a forked child: no wait at all)."""
        if self.forked():
            return
        if self.closing:
            raise greenlet.GreenletExit()
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

    def clock_read(self):
        if greenlet.getcurrent() is not self.program:
            return
        self.clock_reads += 1
        if self.clock_reads >= CLOCK_READS_PER_PERIOD:
            self.wait_period()

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

def describe(exc, tb, path):
    folder = os.path.dirname(path)
    if isinstance(exc, SyntaxError) and _mine(exc.filename, folder):
        text = f"{os.path.basename(exc.filename)}:{exc.lineno}: {type(exc).__name__}: {exc.msg}"
        line = (exc.text or "").strip()
        return text + (f" (`{line}`)" if line else "")
    if isinstance(exc, ExecuteBudgetExceeded):
        what = budget_text + ": interrupted here"
    elif isinstance(exc, ModuleNotFoundError):
        what = (f"ModuleNotFoundError: no module named '{exc.name}' (Aula's Python has Debian's standard "
                "library, numpy, cv2, and RoboticsAcademy's HAL and GUI)")
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
