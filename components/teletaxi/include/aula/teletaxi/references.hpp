#pragma once
// The exercise's own algorithms (references, baselines), each built as a plugin of its own
// (<lib>/aula/references/libaula_teletaxi_<name>.so, --algorithm=<name>): not part of the student's API,
// not installed, and in no component, so a student's plugin cannot reach them (issue 28).

#include <aula/teletaxi/taxi_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::teletaxi {

std::unique_ptr<TaxiAlgorithm> makeReferenceAlgorithm();  // Gradient Path Planning

}  // namespace aula::teletaxi
