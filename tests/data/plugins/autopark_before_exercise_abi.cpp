// An autopark plugin as built before each exercise had an ABI version of its own (issue 59): no
// aula_algorithm_exercise_abi_version(), so it counts as the autopark API's version 1 (a student's
// plugin built on the API before RA's street changed Slot and SlotDetector). Hand-written, since
// aula_add_algorithm writes the current versions.
#include <aula/component/algorithm_plugin.hpp>

AULA_PLUGIN_EXPORT int aula_algorithm_abi_version() { return AULA_ALGORITHM_ABI_VERSION; }
AULA_PLUGIN_EXPORT const char* aula_algorithm_exercise() { return "autopark"; }
AULA_PLUGIN_EXPORT void* aula_autopark_algorithm_v1(unsigned long) { return nullptr; }
