#pragma once
// Exit codes every Aula program uses, and the launcher explains. 128 + N is death by signal N.

namespace aula::process {

constexpr int kExitFinished = 0;        // the run ended as it should
constexpr int kExitFailed = 1;          // a process failed (or a run ended unfinished)
constexpr int kExitUsage = 2;           // usage or configuration error: nothing ran
constexpr int kExitAlgorithmHung = 3;   // a component: the student's code did not return in time
constexpr int kExitAlgorithmExited = 4; // a component: the student's code called exit() inside a call
constexpr int kExitAlgorithmForbidden = 5;  // a component: the student's code tried what a run forbids
// The launcher: the run ended for the machine's reason (machine_reason.hpp), as the launcher itself
// saw it (its backstop, a process of Aula's killed from outside the run); EX_TEMPFAIL.
constexpr int kExitMachine = 75;
constexpr int kExitInterrupted = 130;   // SIGINT
constexpr int kExitTerminated = 143;    // SIGTERM

}  // namespace aula::process
