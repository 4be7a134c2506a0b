// A vacuum plugin built against an older vacuum API (its exercise ABI version one below this
// Aula's), on the common API of this Aula. Hand-written, since aula_add_algorithm writes the
// current versions.
#include <aula/component/algorithm_plugin.hpp>

AULA_PLUGIN_EXPORT int aula_algorithm_abi_version() { return AULA_ALGORITHM_ABI_VERSION; }
AULA_PLUGIN_EXPORT int aula_algorithm_exercise_abi_version() { return AULA_TEST_VACUUM_ABI_VERSION - 1; }
AULA_PLUGIN_EXPORT const char* aula_algorithm_exercise() { return "vacuum"; }
AULA_PLUGIN_EXPORT void* aula_vacuum_algorithm_v1(unsigned long) { return nullptr; }
