#pragma once
// The algorithm's own process (algorithm_box.hpp), the end that hosts the student's code: an
// exercise's main starts with
//   if (aula::component::isAlgorithmBox(argc, argv)) return aula::component::runAlgorithmBox<VacuumBox>();
// `Box` is the exercise's algorithm end: its own devices and API, made from the motors, and
//   using Algorithm = ...;
//   explicit Box(Motors& motors);
//   void readInputs(BoxWire&, CallKind);    // what the component's exchange wrote
//   void invoke(Algorithm&, CallKind);      // execute(api), generatePath(api)...
//   void writeOutputs(BoxWire&, CallKind);  // what the component's exchange reads
// The algorithm is hosted as in the component (AlgorithmHost: budgets, faults, crash report),
// under its Response::EndProcess: whatever ends a call ends this process, and the component
// takes that end as its own.

#include <aula/component/algorithm_box.hpp>
#include <aula/component/algorithm_host.hpp>
#include <aula/component/crash_report.hpp>

#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace aula::component {

// Closes every descriptor but the socket and the line (the bus's, a key's: nothing the
// component had), and reads the start. False when there is none (not started by a component).
bool enterAlgorithmBox(BoxStart& start, AlgorithmBudgets& budgets);
// Says the algorithm cannot be used (PluginError's text) or what was loaded.
void sayRefused(const std::string& why);
void sayLoaded(const AlgorithmHostBase& host);
// Reads the next call's header; false at the end of the stream (the component is done). `names`
// keeps the calls' names for the process's life: the watchdog holds a call's name by pointer.
bool readCall(std::string& frame, BoxWire& wire, uint64_t& seed, CallKind& kind, const char*& what,
              std::set<std::string>& names);
// The process's end once the algorithm has ended: its output flushed, then no library's static
// destructors, which may fail on their own at exit (OMPL 1.5's SelfConfig map: a SIGSEGV after
// every run of the Autopark planner, said as a crash after a good run). Under AddressSanitizer the
// usual exit, for its leak check.
[[noreturn]] void endAlgorithmBox();
void sendReply(const std::string& fault, const std::string& printed, const Motors& motors,
               const std::function<void(BoxWire&)>& outputs);

template <class Box>
int runAlgorithmBox() {
  BoxStart start;
  AlgorithmBudgets budgets;
  if (!enterAlgorithmBox(start, budgets)) return 2;
  Motors motors(start.max_v_mps, start.max_w_radps);
  Box box(motors);
  std::optional<AlgorithmHost<typename Box::Algorithm>> host;
  try {
    host.emplace(start.program, start.exercise, start.choice, motors, budgets);
  } catch (const PluginError& e) {
    sayRefused(e.what());
    return 2;
  }
  sayLoaded(*host);
  std::string frame;
  BoxWire wire = BoxWire::writing();
  uint64_t seed = 0;
  CallKind kind{};
  const char* what = "";
  std::set<std::string> names;
  while (readCall(frame, wire, seed, kind, what, names)) {
    box.readInputs(wire, kind);
    wire.expectEnd("call");
    host->call(seed, what, kind, [&box, kind](typename Box::Algorithm& algorithm) { box.invoke(algorithm, kind); });
    sendReply(host->fault(), host->takePrinted(), motors, [&box, kind](BoxWire& out) { box.writeOutputs(out, kind); });
  }
  host.reset();  // ends the algorithm (its destructor, a Python program's `finally`)
  endAlgorithmBox();
}

}  // namespace aula::component
