// The references' factories by the names they have in their own plugins (references.hpp), defined
// in the component as tripwires: a student's plugin that calls one, linked against it or found by
// name (dlsym, the program's symbol table, ctypes), ends its run with that reason, flagged
// (crash_report.hpp). The references themselves are in no component (issue 28).
#include <aula/component/crash_report.hpp>
#include <aula/vacuum/references.hpp>

namespace aula::vacuum {

std::unique_ptr<VacuumAlgorithm> makeReferenceAlgorithm(uint64_t) {
  component::endForForbiddenCall("call makeReferenceAlgorithm, the reference");
}

std::unique_ptr<VacuumAlgorithm> makeRandomBounceAlgorithm(uint64_t) {
  component::endForForbiddenCall("call makeRandomBounceAlgorithm, the baseline");
}

namespace mapping {
std::unique_ptr<VacuumAlgorithm> makeMappingReferenceAlgorithm(uint64_t seed);  // reference/mapping/
std::unique_ptr<VacuumAlgorithm> makeMappingReferenceAlgorithm(uint64_t) {
  component::endForForbiddenCall("call makeMappingReferenceAlgorithm, the mapping reference");
}
}  // namespace mapping

}  // namespace aula::vacuum
