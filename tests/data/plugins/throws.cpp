// A student's vacuum algorithm that drives forward, then throws on its 6th call.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <stdexcept>

namespace aula::vacuum {
namespace {

class Throws : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    if (++calls_ > 5) throw std::runtime_error("boom");
    api.motors.sendV(0.3);
    api.motors.sendW(0.0);
  }

 private:
  int calls_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Throws>(); }

}  // namespace aula::vacuum
