// The references' factories by the names they have in their own plugins (references.hpp), defined
// in the component as tripwires: a student's plugin that calls one, linked against it or found by
// name (dlsym, the program's symbol table, ctypes), ends its run with that reason, flagged
// (crash_report.hpp). The references themselves are in no component (issue 28).
#include <aula/autopark/references.hpp>
#include <aula/component/crash_report.hpp>

namespace aula::autopark {

std::unique_ptr<AutoparkAlgorithm> makeReactiveAlgorithm(uint64_t) {
  component::endForForbiddenCall("call makeReactiveAlgorithm, the reactive reference");
}

std::unique_ptr<AutoparkAlgorithm> makePlannedAlgorithm(uint64_t) {
  component::endForForbiddenCall("call makePlannedAlgorithm, the planning reference");
}

}  // namespace aula::autopark
