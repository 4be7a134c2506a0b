// A student's vacuum algorithm that looks at what its process holds, and says it as its fault:
// how many descriptors it has open, whether the teacher's environment reached it
// (AULA_TEST_TEACHERS_SECRET, set by the test), whether it runs inside the component (whose
// command line has the run's bus), whether it may open a socket, and whether it may make a
// system call off the algorithm's list (memfd_create: shared memory of its own making).
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

namespace aula::vacuum {
namespace {

class WhatItHolds : public VacuumAlgorithm {
 public:
  void execute(VacuumApi&) override {
    int fds = 0;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd")) {
      (void)entry;
      ++fds;
    }
    --fds;  // the iterator's own
    std::ifstream in("/proc/self/cmdline");
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const int socket_fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    if (socket_fd >= 0) ::close(socket_fd);
    const int memfd = ::memfd_create("what-it-holds", MFD_CLOEXEC);
    if (memfd >= 0) ::close(memfd);
    throw std::runtime_error("holds: fds=" + std::to_string(fds) +
                             " secret=" + (std::getenv("AULA_TEST_TEACHERS_SECRET") != nullptr ? "yes" : "no") +
                             " bus=" + (cmdline.find("--lcm-url") != std::string::npos ? "yes" : "no") +
                             " socket=" + (socket_fd >= 0 ? "yes" : "no") + " memfd=" + (memfd >= 0 ? "yes" : "no"));
  }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<WhatItHolds>(); }

}  // namespace aula::vacuum
