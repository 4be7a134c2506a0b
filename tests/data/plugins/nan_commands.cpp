// A student's vacuum algorithm whose speed is always NaN (0/0 in a real one's arithmetic).
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <limits>

namespace aula::vacuum {
namespace {

class NanCommands : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    api.motors.sendV(std::numeric_limits<double>::quiet_NaN());
    api.motors.sendW(0.0);
  }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<NanCommands>(); }

}  // namespace aula::vacuum
