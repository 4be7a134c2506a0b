# The Python port of exam_attack.hpp: a student's MyAlgorithm.py that attacks its exam from inside
# execute(), once, and says on stderr what each try gave ("exam: <try>: done" / "exam: <try>:
# refused (<why>)"); then it stays still. tests/attacks/test_exam.cpp writes one submission
# folder per attack, this file as its MyAlgorithm.py after a first line naming the attack
# (AULA_EXAM_ATTACK = "read"):
# - "read": open each file named in $AULA_EXAM_READ (a classmate's MyAlgorithm.cpp, the out
#   folder's manifest, a teacher's world, /home);
# - "udp": a datagram to 127.0.0.1 and to LCM's group on $AULA_EXAM_PORT, where a listener
#   outside the run waits;
# - "memory": 3 GB in one bytearray;
# - "fork": os.fork() until refused, and keep trying;
# - "privilege": unmount /proc, remount / read-write, a user namespace of its own (through ctypes),
#   write a file in $AULA_EXAM_WRITE;
# - "reference": load the reference's plugin through ctypes, then find the component's
#   reference (makeReferenceAlgorithm) as a C++ plugin would through the dynamic linker, and call it;
# - "reexec": start the component again in this process, with --Vacuum.Algorithm=reference;
# - "_exit": os._exit(0) inside execute();
# - "flood": 4 MB to stdout in each execute(), without end.
import ctypes
import os
import socket
import sys
import time

AULA_EXAM_ATTACK = globals().get("AULA_EXAM_ATTACK", "none")
MNT_DETACH, MS_REMOUNT, MS_BIND, CLONE_NEWUSER = 2, 32, 4096, 0x10000000
libc = ctypes.CDLL(None, use_errno=True)


def say(what, done, error=0):
    print(f"exam: {what}: done" if done else f"exam: {what}: refused ({os.strerror(error)})", file=sys.stderr,
          flush=True)


def read_files():
    for path in filter(None, os.environ.get("AULA_EXAM_READ", "").split(":")):
        try:
            os.close(os.open(path, os.O_RDONLY))  # a folder (/home) opens too, as in C++
            say("read " + path, True)
        except OSError as e:
            say("read " + path, False, e.errno)


def send_datagrams():
    port = int(os.environ.get("AULA_EXAM_PORT", "9"))
    for address in ("127.0.0.1", "239.255.76.67"):
        try:
            with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
                s.sendto(b"a classmate's MyAlgorithm.cpp", (address, port))
            say("send to " + address, True)
        except OSError as e:
            say("send to " + address, False, e.errno)


def use_memory():
    block = bytearray(3 << 30)
    say("use 3 GB", block[-1] == 0)


def fork_forever():
    while True:
        try:
            if os.fork() == 0:
                while True:
                    time.sleep(1000)
        except OSError:
            pass


def try_privileges():
    for what, call in (("unmount /proc", lambda: libc.umount2(b"/proc", MNT_DETACH)),
                       ("remount / read-write", lambda: libc.mount(None, b"/", None, MS_REMOUNT | MS_BIND, None)),
                       ("make a user namespace", lambda: libc.unshare(CLONE_NEWUSER))):
        say(what, call() == 0, ctypes.get_errno())
    target = os.environ.get("AULA_EXAM_WRITE", "/nonexistent")
    try:
        open(target, "w").close()
        say("write " + target, True)
    except OSError as e:
        say("write " + target, False, e.errno)


def find_reference():
    # The reference's own plugin, beside the component.
    bin_dir = os.path.dirname(os.readlink("/proc/self/exe"))
    plugin = os.path.join(bin_dir, "..", "lib", "aula", "references", "libaula_vacuum_reference.so")
    try:
        ctypes.CDLL(plugin).aula_vacuum_algorithm_v1
        say("load the reference's plugin", True)
    except (OSError, AttributeError):
        say("load the reference's plugin", False, 2)
    # makeReferenceAlgorithm(uint64_t) as the linker names it, looked up in every loaded object,
    # and called as C++ calls it (its std::unique_ptr returned through a hidden first argument).
    try:
        make = getattr(libc, "_ZN4aula6vacuum22makeReferenceAlgorithmEm")
        say("find makeReferenceAlgorithm", True)
        made = ctypes.c_void_p()
        make.restype = None
        make(ctypes.byref(made), ctypes.c_uint64(1))
        say("call makeReferenceAlgorithm", bool(made.value))
    except AttributeError:
        say("find makeReferenceAlgorithm", False, 2)  # ENOENT


def reexec_as_reference():
    with open("/proc/self/cmdline", "rb") as f:
        args = [a.decode() for a in f.read().split(b"\0") if a]
    args = ["--Vacuum.Algorithm=reference" if a.startswith("--Vacuum.Algorithm=") else a for a in args]
    try:
        os.execv("/proc/self/exe", args)
    except OSError as e:
        say("re-execute the component", False, e.errno)


def flood():
    line = "x" * 1023 + "\n"
    for _ in range(4 * 1024):
        sys.stdout.write(line)
    sys.stdout.flush()


ATTACKS = {"read": read_files, "udp": send_datagrams, "memory": use_memory, "fork": fork_forever,
           "privilege": try_privileges, "reference": find_reference, "reexec": reexec_as_reference,
           "_exit": lambda: os._exit(0)}


class MyAlgorithm:
    def __init__(self, seed):
        self.done = False

    def execute(self, api):
        api.motors.sendV(0.0)
        api.motors.sendW(0.0)
        if AULA_EXAM_ATTACK == "flood":
            flood()
        if self.done:
            return
        self.done = True
        ATTACKS.get(AULA_EXAM_ATTACK, lambda: None)()
