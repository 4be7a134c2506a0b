#pragma once
// The component's own algorithms (references and baselines): not part of the student's API (not
// installed, not exported to plugins: cmake/aula_plugin_exports.list), so a student's plugin cannot
// reach them.

#include <aula/teletaxi/taxi_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::teletaxi {

std::unique_ptr<TaxiAlgorithm> makeReferenceAlgorithm();  // Gradient Path Planning

}  // namespace aula::teletaxi
