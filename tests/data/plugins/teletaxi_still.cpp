// A valid TeleTaxi algorithm (it keeps the taxi still): loaded by the vacuum cleaner, the wrong exercise.
#include <aula/teletaxi/taxi_algorithm.hpp>

namespace aula::teletaxi {
namespace {

class Still : public TaxiAlgorithm {
 public:
  void generatePath(TaxiApi&) override {}
  void execute(TaxiApi& api) override {
    api.vel.setV(0.0);
    api.vel.setW(0.0);
  }
};

}  // namespace

std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm() { return std::make_unique<Still>(); }

}  // namespace aula::teletaxi
