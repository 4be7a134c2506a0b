#pragma once
// The one flow of every referee process. Headless: handle the bus until the episode ends (or a
// signal), then print the mark and write the report. With a display: the referee's window,
// which shows the mark by itself at the end (the same summary and report are written then).
//
// `--replay=FILE.lcmlog` grades a recorded run instead (`aula regrade`): the log's events in
// order, through the same handlers, to the end of the episode; a log that ends first exits 1.
//
// The launcher's `--control-fd` pipe can end the run early ("abort <reason>"): the node grades
// what it has and says why; such a run exits 1 (it did not finish). Without a launcher (three
// terminals) the referee watches its peers itself (Node::peersGone: the component left or died,
// the simulator ended the run or stopped) and ends the same way. With a window, a run ended early
// ends the process too (the report is written, the terminal says why): the launcher then stops
// the rest. A replay's window (--view-only, `aula replay`) watches nothing: a replay pauses and ends.
//
// `--picture=FILE.png` writes the referee's picture of the run (drawn headless with OpenCV, for
// the teacher's grading report) at the same moment as the report; `--trace=FILE.json` the
// run's trace for the grading page's player (aula/referee/run_trace.hpp).
//
// Node needs finished(), endedEarly(), abort(reason), aborted(), poll(), peersGone(), leave(), deferSensorWakeUps(bus), summary(),
// report(), writePicture(path), writeTrace(path), setOnFinished(hook);
// Window needs Window(Node&), showMark(); with `--screenshot=FILE.png` the window is saved when
// the episode ends, its mark shown (gui::screenshotWhenFinished).

#include <aula/app/bus_pump.hpp>
#include <aula/app/main_window.hpp>
#include <aula/app/process_setup.hpp>
#include <aula/config/paths.hpp>
#include <aula/gui/screenshot.hpp>
#include <aula/lcm/log_replay.hpp>
#include <aula/process/exit_codes.hpp>
#include <aula/process/line_pipe.hpp>

#include <QApplication>

#include <iostream>
#include <string>

namespace aula::app {

// The options of every referee: ProcessSetup::fromArgs plus the output files, whose folders are
// checked now, before the run starts (a ConfigError, exit code 2, naming the path).
inline ProcessSetup refereeSetup(int argc, const char* const* argv, const std::string& program, const std::string& usage) {
  ProcessSetup setup = ProcessSetup::fromArgs(argc, argv, program, {"report", "picture", "trace", "screenshot"}, usage);
  for (const char* option : {"report", "picture", "trace", "screenshot"}) {
    if (!setup.command_line.flag(option)) continue;
    const std::string path = setup.command_line.option(option);
    config::requireWritableFolder(path, std::string("--") + option + "=" + path);
  }
  return setup;
}

template <class Node, class Window>
int runReferee(ProcessSetup& setup, Node& node, int argc, char** argv) {
  const std::string report_path = setup.command_line.option("report");
  const std::string picture_path = setup.command_line.option("picture");
  const std::string trace_path = setup.command_line.option("trace");
  process::LinePipe control(setup.command_line.flag("control-fd")
                          ? static_cast<int>(setup.command_line.optionDouble("control-fd", -1))
                          : -1);
  // "discard": the run never started (a process refused its settings or plugin): no mark at
  // all, and no report, rather than a mark for a robot that was never given a chance.
  bool discard = false;
  auto readControl = [&] {
    for (const std::string& line : control.lines()) {
      if (line.rfind("fault ", 0) == 0) node.algorithmFailed(line.substr(6));
      if (line.rfind("abort ", 0) == 0) node.abort(line.substr(6));
      if (line == "discard") discard = true;
      if (line.rfind("escape ", 0) == 0) node.escapeAttempt(line.substr(7));
    }
  };
  // Alone, a peer gone ends the run (graded so far); true once the run cannot go on.
  const bool watch_peers = !setup.command_line.flag("control-fd") && !setup.command_line.flag("view-only");
  auto peersGone = [&] {
    if (!watch_peers) return false;
    const std::string why = node.peersGone();
    if (why.empty()) return false;
    if (!node.finished()) {
      std::cerr << setup.program << ": " << why << ": the run ends" << std::endl;
      node.abort(why);
    }
    return true;
  };
  auto housekeeping = [&] {  // true once a peer is gone
    node.poll();
    readControl();
    return peersGone();
  };
  auto finish = [&] {
    readControl();
    if (discard) {
      std::cout << "no mark: the run never started (the reason is above)\n" << std::flush;
      return;
    }
    std::cout << node.summary() << std::flush;
    if (!report_path.empty()) {
      // How the run was confined, as the launcher said (--isolation): a run without the sandbox says so.
      const std::string isolation = setup.command_line.option("isolation", "none");
      auto report = node.report();
      report.set("sandboxed", isolation != "none");
      report.set("isolation", isolation);
      report.writeAtomically(report_path);
    }
    if (!picture_path.empty()) node.writePicture(picture_path);
    if (!trace_path.empty()) node.writeTrace(trace_path);
  };
  if (setup.command_line.flag("replay")) {
    // The recorded run, graded on its own clock: the same handlers see the same messages.
    const bool log_ended = lcmbus::replayLog(*setup.bus, setup.command_line.option("replay"),
                                             [&] { return node.finished(); }, [&] { node.poll(); });
    node.leave();
    if (log_ended && !node.finished()) std::cout << "(the log ends before the end of the episode)\n";
    finish();
    return node.endedEarly() || !node.finished() ? 1 : 0;
  }
  if (setup.headless) {
    if (trace_path.empty()) node.leaveOutTraceLayers(*setup.bus);
    node.deferSensorWakeUps(*setup.bus);  // woken at its own ticks, not at every one
    const bool signalled = runHeadless(*setup.bus, [&] { return node.finished(); }, housekeeping);
    node.leave();
    readControl();
    if (signalled && !node.finished() && !discard) std::cout << "(stopped before the end of the episode)\n";
    finish();
    return discard ? 2 : node.endedEarly() ? 1 : 0;
  }
  QApplication app(argc, argv);
  Window window(node);
  BusPump pump(*setup.bus, [&] {
    const bool gone = housekeeping();
    if (node.aborted()) QCoreApplication::exit(process::kExitFailed);
    else if (gone) QCoreApplication::exit(0);  // graded to the end before its peers went
  });
  node.setOnFinished([&] {
    window.showMark();
    finish();
  });
  placeMainWindow(window, setup.program, setup.cfg);
  quitWhenClosed(window);
  window.show();
  if (setup.command_line.flag("screenshot")) {
    gui::screenshotWhenFinished(window, [&node] { return node.finished(); }, [&window] { window.showMark(); },
                                QString::fromStdString(setup.command_line.option("screenshot")));
  }
  const int code = app.exec();
  node.leave();
  // Closed or stopped (Ctrl-C) before this episode's end: the report is this episode's, graded so
  // far, not the one a finished episode before a reload left.
  if (!node.finished() && !discard) {
    std::cout << "(stopped before the end of the episode)\n";
    finish();
  }
  return code;
}

}  // namespace aula::app
