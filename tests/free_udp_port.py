"""Prints a UDP port the OS hands out (bound to port 0, then released): a test's private LCM port.

The kernel never hands out a port another socket is bound to, and the LCM sockets of a running
test stay bound to theirs, so two tests at once (or two checkouts' test suites) do not meet on
one port, as they could with ports drawn at random.
"""
import socket

with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
    probe.bind(("", 0))
    print(probe.getsockname()[1])
