// A student's vacuum algorithm whose execute() recurses until the stack overflows (SIGSEGV on
// the guard page): each frame keeps a buffer the compiler cannot drop.
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

__attribute__((noinline)) int recurse(int depth) {
  volatile char frame[4096];
  frame[0] = static_cast<char>(depth);
  return depth < 0 ? 0 : recurse(depth + 1) + frame[0];
}

class StackOverflow : public VacuumAlgorithm {
 public:
  void execute(VacuumApi&) override { result_ = recurse(1); }

 private:
  int result_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<StackOverflow>(); }

}  // namespace aula::vacuum
