#pragma once
// The exercise's own algorithms (references, baselines), each built as a plugin of its own
// (<lib>/aula/references/libaula_vacuum_<name>.so, --algorithm=<name>): not part of the student's API,
// not installed, and in no component, so a student's plugin cannot reach them (issue 28).

#include <aula/vacuum/vacuum_algorithm.hpp>

#include <cstdint>
#include <memory>

namespace aula::vacuum {

std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t seed);   // spiral, wall, bounce: --algorithm=classic
std::unique_ptr<VacuumAlgorithm> makeRandomBounceAlgorithm(uint64_t seed);  // the baseline

}  // namespace aula::vacuum
