#pragma once
// When the student's code crashes the component (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT), the
// stack is printed before the process dies of the same signal (the launcher still sees it and
// names it): the frames in the plugin show as lib<name>.so(+0xOFFSET), and the last line says
// how to turn an offset into a file and line (addr2line on the plugin, built with -g by
// aula_add_algorithm).

#include <string>

namespace aula::component {

// Once per process, before student code runs. `plugin_path` may be "" (a built-in) and is
// updated by a later call (hot reload).
void installCrashReport(const std::string& program, const std::string& plugin_path);

}  // namespace aula::component
