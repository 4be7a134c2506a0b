// A TeleTaxi algorithm that opens the "Grid Field" window from generatePath(), as a student's
// does, and keeps the taxi still: the GUI test closes the main window while the grid's is open.
#include <aula/teletaxi/taxi_algorithm.hpp>

namespace aula::teletaxi {
namespace {

class ShowsGrid : public TaxiAlgorithm {
 public:
  void generatePath(TaxiApi& api) override { api.grid.showGrid(); }
  void execute(TaxiApi& api) override {
    api.vel.setV(0.0);
    api.vel.setW(0.0);
  }
};

}  // namespace

std::unique_ptr<TaxiAlgorithm> makeStudentAlgorithm() { return std::make_unique<ShowsGrid>(); }

}  // namespace aula::teletaxi
