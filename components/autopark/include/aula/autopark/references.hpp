#pragma once
// The exercise's own algorithms (references, baselines), each built as a plugin of its own
// (<lib>/aula/references/libaula_autopark_<name>.so, --algorithm=<name>): not part of the student's API,
// not installed, and in no component, so a student's plugin cannot reach them (issue 28).

#include <aula/autopark/autopark_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::autopark {

// The thesis's reactive solution: find the slot, stop alongside the car ahead, reverse in two arcs, centre.
std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t seed);
// Maps the street from the lasers, plans a Reeds-Shepp path into the slot (OMPL), tracks it.
std::unique_ptr<AutoparkAlgorithm> makePlannedAlgorithm(uint64_t seed);

}  // namespace aula::autopark
