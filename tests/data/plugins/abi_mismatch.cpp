// A vacuum plugin built against another Aula: its entry points claim algorithm ABI 999.
// Hand-written (a plain add_library(MODULE)), since aula_add_algorithm writes the current ABI.
extern "C" __attribute__((visibility("default"))) int aula_algorithm_abi_version() { return 999; }
extern "C" __attribute__((visibility("default"))) const char* aula_algorithm_exercise() { return "vacuum"; }
