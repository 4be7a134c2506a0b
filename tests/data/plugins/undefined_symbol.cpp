// A student's vacuum algorithm that calls a function this Aula does not have (built against
// another version, or a typo in a helper's name): dlopen fails with "undefined symbol".
#include <aula/vacuum/vacuum_algorithm.hpp>

extern void aula_test_function_that_does_not_exist();

namespace aula::vacuum {
namespace {

class UndefinedSymbol : public VacuumAlgorithm {
 public:
  void execute(VacuumApi&) override { aula_test_function_that_does_not_exist(); }
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<UndefinedSymbol>(); }

}  // namespace aula::vacuum
