#pragma once
// Integration tests talk over a private UDP multicast port, so parallel ctest runs never cross
// (a different group on the same port still receives the cross-talk: isolate by port).

#include <string>

#include <unistd.h>

namespace aula::testing {

inline std::string privateLcmUrl() {
  const int port = 17000 + static_cast<int>(getpid() % 20000);
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

}  // namespace aula::testing
