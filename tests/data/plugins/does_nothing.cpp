// A student's vacuum algorithm that never sends a command.
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

class DoesNothing : public VacuumAlgorithm {
 public:
  void execute(VacuumApi&) override {}
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<DoesNothing>(); }

}  // namespace aula::vacuum
