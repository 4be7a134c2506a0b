#pragma once
// When the student's code crashes the component (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT), the
// student is told where, in their own lines (plugin_lines.hpp: addr2line on the plugin, built
// with -g by aula_add_algorithm), innermost first:
//   vacuum-cleaner: crashed (SIGSEGV) in your algorithm at MyAlgorithm.cpp:14 (MyAlgorithm::execute)
//     called from MyAlgorithm.cpp:30 (MyAlgorithm::turn)
// A crash with no frame in the plugin (a built-in, the component itself) prints the raw stack.
// Then the process dies of the same signal (the launcher still sees it and names it), having
// written one line, "crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)", on the
// launcher's private line when it has one (reportCrashesTo).
//
// With windows, a crash inside a call into the algorithm need not end the process:
// callSurvivingCrashes runs the call so that SIGSEGV, SIGBUS, SIGFPE or SIGILL returns there with
// that line instead (the handler jumps back, on an alternate stack, so a stack overflow too).
// Everything the handler needs is prepared beforehand, in fixed buffers: it allocates nothing.

#include <aula/component/plugin_lines.hpp>

#include <functional>
#include <string>

namespace aula::component {

// Once per process, before student code runs; again with the plugin's image after each load
// (hot reload). `plugin` has an empty path for a built-in or a Python file. Gives the calling
// thread an alternate signal stack.
void installCrashReport(const std::string& program, const PluginImage& plugin);

// The launcher's private line for the crash's one line (a descriptor of this process), or -1.
void reportCrashesTo(int fd);
// That descriptor, or -1 (the algorithm's own process passes its lines on there).
int crashLineFd();

// The student's code called what no student's algorithm may (`what`: "call
// makeReferenceAlgorithm", from a tripwire of the component's): the process ends with that reason,
// said on the launcher's private line too, which flags the run (sandbox::endForForbiddenTry).
[[noreturn]] void endForForbiddenCall(const std::string& what);
// Ends the process for a call that overran its budget (ExecuteWatchdog): `why` on stderr and, as
// "overran WHY", on the launcher's private line; exit code kExitAlgorithmHung. Nothing is flushed
// or destroyed: the stuck thread holds whatever it holds.
[[noreturn]] void endForOverrun(const std::string& program, const std::string& why);
// The private line's prefix of that reason.
extern const char* const kOverranPrefix;

// An object a crash left behind (a crashed algorithm) is never destroyed, since its destructor
// could crash again; this says so to LeakSanitizer in a sanitizer build (nothing otherwise).
void abandonAfterCrash(const void* object);

// For a thread that runs student calls under callSurvivingCrashes: an alternate signal stack,
// and the fault signals unblocked (a blocked SIGSEGV would kill the process whatever the handler).
void prepareThreadForCrashes();

// Runs `call` on this thread (prepared with prepareThreadForCrashes); "" when it returned, or
// the crash that ended it ("crashed (SIGSEGV) at MyAlgorithm.cpp:14 (MyAlgorithm::execute)").
// What `call` throws passes through. Whatever the crashed call owned is left as it was: never
// destroy or call into the algorithm again.
std::string callSurvivingCrashes(const std::function<void()>& call);

}  // namespace aula::component
