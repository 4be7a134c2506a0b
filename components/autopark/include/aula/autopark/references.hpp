#pragma once
// The component's own algorithms (references and baselines): not part of the student's API (not
// installed, not exported to plugins: cmake/aula_plugin_exports.list), so a student's plugin cannot
// reach them.

#include <aula/autopark/autopark_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::autopark {

// The thesis's reactive solution: find the slot, stop alongside the car ahead, reverse in two arcs, centre.
std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t seed);
// Maps the street from the lasers, plans a Reeds-Shepp path into the slot (OMPL), tracks it.
std::unique_ptr<AutoparkAlgorithm> makePlannedAlgorithm(uint64_t seed);

}  // namespace aula::autopark
