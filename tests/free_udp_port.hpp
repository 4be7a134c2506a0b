#pragma once
// A UDP port the OS hands out (bound to port 0, then released): a test's private LCM port. The
// kernel never hands out a port a running test's LCM sockets are bound to, so tests at once (or
// two checkouts' suites) never meet on one port, as they could with ports drawn at random.
// (tests/free_udp_port.py does the same for the shell tests.)

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <stdexcept>

namespace aula::testing {

inline int freeUdpPort() {
  const int probe = socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  socklen_t size = sizeof address;
  const bool bound = probe >= 0 && bind(probe, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
                     getsockname(probe, reinterpret_cast<sockaddr*>(&address), &size) == 0;
  if (probe >= 0) close(probe);
  if (!bound) throw std::runtime_error("cannot get a free UDP port from the OS");
  return ntohs(address.sin_port);
}

}  // namespace aula::testing
