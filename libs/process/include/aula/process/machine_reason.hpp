#pragma once
// A run that ends for the machine's reason, not the algorithm's: a process killed from outside
// the run (the out-of-memory killer), a process that died that is not the student's, a wall-clock
// backstop that ran out on a starved machine. Such a reason's text starts with kMachineReason:
// `aula run` says so, and `aula grade` and `aula calibrate` run it again; it never becomes a mark.

#include <string>

namespace aula::process {

inline constexpr const char* kMachineReason = "the machine's reason: ";

inline std::string machineReason(const std::string& what) { return kMachineReason + what; }

// Is `text` (a report's `aborted`, a run's failure) the machine's reason?
inline bool isMachineReason(const std::string& text) { return text.find(kMachineReason) != std::string::npos; }

}  // namespace aula::process
