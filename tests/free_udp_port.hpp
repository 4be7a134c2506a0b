#pragma once
// A UDP port the OS hands out: a test's private LCM port (lcmbus::freeUdpPort). The kernel never
// hands out a port a running test's LCM sockets are bound to, so tests at once (or two
// checkouts' suites) never meet on one port, as they could with ports drawn at random.
// (tests/free_udp_port.py does the same for the shell tests.)

#include <aula/lcm/bus.hpp>

namespace aula::testing {

inline int freeUdpPort() { return lcmbus::freeUdpPort(); }

}  // namespace aula::testing
