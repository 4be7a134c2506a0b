// A student's vacuum algorithm that, at its first execute(), runs its own program again with its
// own command line (as the exam's "reexec" attack does): inside the component, a second component;
// in its own process, a second algorithm's process, with no component to talk to.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace aula::vacuum {
namespace {

class Reexec : public VacuumAlgorithm {
 public:
  void execute(VacuumApi&) override {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::vector<std::string> args;
    for (std::string arg; std::getline(in, arg, '\0');) args.push_back(arg);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv("/proc/self/exe", argv.data());
  }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Reexec>(); }

}  // namespace aula::vacuum
