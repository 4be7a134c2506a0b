// The reference's factory by the name it has in its own plugin (references.hpp), defined in the
// component as a tripwire: a student's plugin that calls it, linked against it or found by name
// (dlsym, the program's symbol table, ctypes), ends its run with that reason, flagged
// (crash_report.hpp). The reference itself is in no component (issue 28).
#include <aula/component/crash_report.hpp>
#include <aula/teletaxi/references.hpp>

namespace aula::teletaxi {

std::unique_ptr<TaxiAlgorithm> makeReferenceAlgorithm() {
  component::endForForbiddenCall("call makeReferenceAlgorithm, the reference");
}

}  // namespace aula::teletaxi
