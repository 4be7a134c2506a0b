// A student's vacuum algorithm that drives forward, then never returns from its 6th call.
// The volatile keeps the loop from being optimised away (an empty endless loop is undefined).
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

class EndlessLoop : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    if (++calls_ > 5) {
      for (;;) {
        volatile int spin = 0;
        (void)spin;
      }
    }
    api.motors.sendV(0.3);
    api.motors.sendW(0.0);
  }

 private:
  int calls_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<EndlessLoop>(); }

}  // namespace aula::vacuum
