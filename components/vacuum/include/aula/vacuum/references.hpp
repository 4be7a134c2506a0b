#pragma once
// The component's own algorithms (references and baselines): not part of the student's API (not
// installed, not exported to plugins: cmake/aula_plugin_exports.list), so a student's plugin cannot
// reach them.

#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::vacuum {

std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t seed);   // spiral, wall, bounce
std::unique_ptr<VacuumAlgorithm> makeRandomBounceAlgorithm(uint64_t seed);  // the baseline

}  // namespace aula::vacuum
