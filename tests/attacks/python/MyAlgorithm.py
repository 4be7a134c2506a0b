# The Python port of escape_from_execute.cpp: a student's MyAlgorithm.py that tries to leave its
# process from inside execute(), once, and says on stderr what each try gave ("escape: <try>:
# done" or "escape: <try>: refused (...)"): write a file into escape-target-python beside the
# component's program (found from /proc/self/exe: a sandboxed run has none of the test's
# environment), find the
# simulator and the referee in /proc, open a TCP and a Unix socket, ptrace another process.
# Sandboxed (`aula run --sandbox`, `aula grade`) every try must be refused, as for C++.
import ctypes
import os
import socket
import sys

PTRACE_ATTACH, PTRACE_DETACH = 16, 17


def say(what, done, error=0):
    print(f"escape: {what}: done" if done else f"escape: {what}: refused ({os.strerror(error)})", file=sys.stderr,
          flush=True)


def try_everything():
    folder = os.path.join(os.path.dirname(os.readlink("/proc/self/exe")), "escape-target-python")
    try:
        open(os.path.join(folder, "escaped.txt"), "w").close()
        say("write a file outside", True)
    except OSError as e:
        say("write a file outside", False, e.errno)
    others = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            cmdline = open(f"/proc/{name}/cmdline", "rb").read()
        except OSError:
            continue
        if b"aula-sim" in cmdline or b"referee" in cmdline:
            others.append(int(name))
    say("see the simulator or the referee in /proc", bool(others), 0 if others else 3)  # ESRCH
    for what, family in (("open a TCP socket", socket.AF_INET), ("open a Unix socket", socket.AF_UNIX)):
        try:
            socket.socket(family, socket.SOCK_STREAM).close()
            say(what, True)
        except OSError as e:
            say(what, False, e.errno)
    libc = ctypes.CDLL(None, use_errno=True)
    target = others[0] if others else os.getppid()
    if libc.ptrace(PTRACE_ATTACH, target, None, None) == 0:
        os.waitpid(target, 0)
        libc.ptrace(PTRACE_DETACH, target, None, None)
        say("ptrace another process", True)
    else:
        say("ptrace another process", False, ctypes.get_errno())


class MyAlgorithm:
    def __init__(self, seed):
        self.tried = False

    def execute(self, api):
        api.motors.sendV(0.0)
        api.motors.sendW(0.0)
        if not self.tried:
            self.tried = True
            try_everything()
