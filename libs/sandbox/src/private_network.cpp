#include "aula/sandbox/sandbox.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include <arpa/inet.h>
#include <net/if.h>
#include <net/route.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace aula::sandbox {
namespace {

std::string failed(const std::string& what) { return what + ": " + std::strerror(errno); }

bool writeProc(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.flush();
  return static_cast<bool>(out);
}

// The loopback up, and 224.0.0.0/4 routed through it (LCM's multicast group), through the same
// ioctls `ifconfig` and `route` use.
std::string loopbackWithMulticast() {
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return failed("socket");
  ifreq interface{};
  std::strncpy(interface.ifr_name, "lo", IFNAMSIZ - 1);
  std::string problem;
  if (::ioctl(fd, SIOCGIFFLAGS, &interface) != 0) problem = failed("the loopback's flags");
  interface.ifr_flags |= IFF_UP | IFF_RUNNING;
  if (problem.empty() && ::ioctl(fd, SIOCSIFFLAGS, &interface) != 0) problem = failed("bringing the loopback up");
  rtentry route{};
  auto* destination = reinterpret_cast<sockaddr_in*>(&route.rt_dst);
  auto* mask = reinterpret_cast<sockaddr_in*>(&route.rt_genmask);
  destination->sin_family = mask->sin_family = AF_INET;
  destination->sin_addr.s_addr = htonl(0xE0000000u);  // 224.0.0.0
  mask->sin_addr.s_addr = htonl(0xF0000000u);         // /4
  route.rt_flags = RTF_UP;
  char device[] = "lo";
  route.rt_dev = device;
  if (problem.empty() && ::ioctl(fd, SIOCADDRT, &route) != 0) problem = failed("the multicast route");
  ::close(fd);
  return problem;
}

}  // namespace

std::string enterPrivateNetwork() {
  const uid_t uid = ::geteuid();
  const gid_t gid = ::getegid();
  if (uid == 0) {
    if (::unshare(CLONE_NEWNET) != 0) return failed("a network namespace (unshare)");
  } else {
    if (::unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) return failed("a user and network namespace (unshare)");
    // Root of the new user namespace, mapped to who we are: enough to set up its network.
    if (!writeProc("/proc/self/setgroups", "deny") || !writeProc("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1") ||
        !writeProc("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1")) {
      return failed("mapping the user into its namespace");
    }
  }
  const std::string problem = loopbackWithMulticast();
  if (!problem.empty()) throw std::runtime_error("the run's private network: " + problem);
  return "";
}

}  // namespace aula::sandbox
