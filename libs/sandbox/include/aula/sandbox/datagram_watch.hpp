#pragma once
// In a run's private network (enterPrivateNetwork), the launcher's watch on datagrams sent
// anywhere but the run's own LCM port: nothing there listens (no other run shares the namespace),
// so such a datagram went nowhere, but it is what a student's code does to reach a classmate's
// run or a listener outside, and the run is flagged for it.
//
// A packet socket on the namespace's loopback (the launcher is root in the namespace's user
// namespace, or root), with a kernel filter that keeps only arriving UDP datagrams (first
// fragments; the loopback shows each datagram, unicast or multicast, once as arriving) whose
// destination port is not the run's: the run's own LCM traffic never wakes the
// launcher.

#include <string>
#include <vector>

namespace aula::sandbox {

class DatagramWatch {
 public:
  // Starts watching; `lcm_port` is the run's. Throws std::runtime_error naming what failed (no
  // CAP_NET_RAW in this namespace: not a private network of ours).
  explicit DatagramWatch(int lcm_port);
  ~DatagramWatch();
  DatagramWatch(const DatagramWatch&) = delete;
  DatagramWatch& operator=(const DatagramWatch&) = delete;

  int fd() const { return fd_; }  // readable when a datagram was seen (poll it)
  // What was seen since the last call, one entry per datagram: "datagram to 127.0.0.1:9".
  std::vector<std::string> seen();

 private:
  int fd_ = -1;
};

}  // namespace aula::sandbox
