// The mapping reference as a student's plugin, built from these sources alone against an
// installed Aula (tests/install/test_mapping_reference.sh):
//   aula run vacuum --algorithm=PATH/libmy_algorithm.so
#include "mapping_reference.hpp"

namespace aula::vacuum {

std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return mapping::makeMappingReferenceAlgorithm(seed); }

}  // namespace aula::vacuum
