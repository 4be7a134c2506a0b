// A student's vacuum algorithm that drives, then reads beam 500 of 180 with .at() on its 6th call
// (line 13): the C++ runtime throws std::out_of_range from inside the library; the fault must
// still name this file's line.
#include <aula/vacuum/vacuum_algorithm.hpp>

namespace aula::vacuum {
namespace {

class OutOfRange : public VacuumAlgorithm {
 public:
  void execute(VacuumApi& api) override {
    const int beam = ++calls_ > 5 ? 500 : 90;
    const float front_m = api.laser.getLaserData().values_m.at(beam);
    api.motors.sendV(front_m > 0.5f ? 0.3 : 0.0);
    api.motors.sendW(0.0);
  }

 private:
  int calls_ = 0;
};

}  // namespace

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t) { return std::make_unique<OutOfRange>(); }

}  // namespace aula::vacuum
