// A student's vacuum algorithm that drives forward, then writes through a null pointer on its
// 6th call (SIGSEGV). Both the pointer and what it points to are volatile: the compiler can
// neither prove the pointer null nor drop the write (with a volatile pointer alone, GCC -O3 does).
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

class Segfault : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    if (++calls_ > 5) {
      volatile int* volatile nowhere = nullptr;
      *nowhere = calls_;
    }
    api.motors.sendV(0.3);
    api.motors.sendW(0.0);
  }

 private:
  int calls_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<Segfault>(); }

}  // namespace aula::vacuum
