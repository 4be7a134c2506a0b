#pragma once
// A run that ends for the machine's reason, not the algorithm's: a process killed from outside
// the run (the out-of-memory killer), a process that died that is not the student's, a wall-clock
// backstop that ran out on a starved machine. Such a reason's text starts with kMachineReason, for
// the people who read it; whether a run ended so is never read back from text (a student's
// exception or compiler error can say anything): the launcher that saw it exits with
// kExitMachine, and `aula grade` writes its own verdict (`machine_reason`) into the run's result.
// `aula grade` and `aula calibrate` run such a run again; it never becomes a mark.

#include <string>

namespace aula::process {

inline constexpr const char* kMachineReason = "the machine's reason: ";

inline std::string machineReason(const std::string& what) { return kMachineReason + what; }

// Does `text` start as a machine's reason does? Only for text from a line the student's code cannot
// write (the simulator's status pipe, the launcher's own verdicts): never to judge a report.
inline bool saysMachineReason(const std::string& text) { return text.rfind(kMachineReason, 0) == 0; }

}  // namespace aula::process
