// The three-terminal mode (README, "Three terminals, like the original"): aula-sim, the component
// and the referee started by hand, no launcher watching them. Killing any one of them ends the
// other two within 5 s, and each says why: the clients see the simulator's clock stop, the
// simulator sees a client's process gone without leaving and ends the run, and the referee's
// report says "aborted" with the reason and "finished": false.
#include <aula/process/child_process.hpp>
#include <aula/process/exit_codes.hpp>

#include "test_support.hpp"

#include <array>
#include <chrono>
#include <csignal>
#include <memory>
#include <string>
#include <thread>

using aula::process::ChildProcess;
using aula::testing::privateDir;
using aula::testing::privateLcmUrl;
using aula::testing::readFile;
using namespace std::chrono_literals;

namespace {

const std::string kBin = AULA_BIN_DIR;
const std::string kWorld = std::string(AULA_SOURCE_DIR) + "/worlds/cityLarge.world";

enum Process { kSimulator = 0, kComponent = 1, kReferee = 2 };
const std::array<const char*, 3> kNames = {"aula-sim", "teletaxi", "teletaxi-referee"};

// The three processes as a student starts them, each in its own "terminal" (its own log), the
// simulator free-running at real time; the taxi drives to a far destination, so the episode is
// still on when one of them is killed.
class ThreeTerminals {
 public:
  ThreeTerminals() : dir_(privateDir()) {
    const std::string url = "--lcm-url=" + privateLcmUrl();
    const std::string world = "--TeleTaxi.World=" + kWorld;
    lines_ = {{{kBin + "/aula-sim", kWorld, url},
               {kBin + "/teletaxi", "--headless", url, world, "--TeleTaxi.Algorithm=reference",
                "--TeleTaxi.Autostart=true", "--TeleTaxi.Destination=220,240"},
               {kBin + "/teletaxi-referee", "--headless", url, world, "--report=" + report()}}};
    for (size_t i = 0; i < lines_.size(); ++i) {
      processes_[i] = std::make_unique<ChildProcess>(lines_[i], log(i), log(i));
    }
  }

  std::string log(size_t i) const { return dir_ + "/" + kNames[i] + ".log"; }
  std::string output(size_t i) const { return readFile(log(i)); }
  std::string report() const { return dir_ + "/report.json"; }
  ChildProcess& process(size_t i) { return *processes_[i]; }

  // Until the simulator has listed both clients and the taxi has driven a little (the run is on).
  bool waitUntilRunning() {
    const auto until = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < until) {
      const std::string sim = output(kSimulator);
      if (sim.find("'teletaxi' joined") != std::string::npos && sim.find("'teletaxi-referee' joined") != std::string::npos) {
        std::this_thread::sleep_for(1500ms);
        return true;
      }
      std::this_thread::sleep_for(100ms);
    }
    return false;
  }

  // SIGKILL: no goodbye, no leave message. Reaped at once, as a shell would.
  void kill(size_t i) {
    ::kill(process(i).pid(), SIGKILL);
    process(i).wait(5s);
  }

 private:
  std::string dir_;
  std::array<std::vector<std::string>, 3> lines_;
  std::array<std::unique_ptr<ChildProcess>, 3> processes_;
};

// Both others end within 5 s of `victim`'s death (measured from the kill).
void expectTheOthersEnd(ThreeTerminals& run, Process victim, std::array<std::optional<int>, 3>& codes) {
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  for (size_t i = 0; i < 3; ++i) {
    if (i == static_cast<size_t>(victim)) continue;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    codes[i] = run.process(i).wait(std::max(left, 1ms));
    EXPECT_TRUE(codes[i].has_value()) << kNames[i] << " still runs 5 s after " << kNames[victim] << " was killed:\n"
                                      << run.output(i);
  }
}

// Kills a client once the run is on: the simulator ends the run (exit 1) and says which client's
// process is gone. Returns its words.
std::string killAClient(ThreeTerminals& run, Process victim, std::array<std::optional<int>, 3>& codes) {
  EXPECT_TRUE(run.waitUntilRunning()) << run.output(kSimulator);
  const pid_t pid = run.process(victim).pid();
  run.kill(victim);
  expectTheOthersEnd(run, victim, codes);
  const std::string why = std::string("lockstep client '") + kNames[victim] + "' (pid " + std::to_string(pid) +
                          ") is gone without leaving the run";
  EXPECT_EQ(codes[kSimulator], aula::process::kExitFailed);
  EXPECT_NE(run.output(kSimulator).find(why + ": the run ends"), std::string::npos) << run.output(kSimulator);
  return why;
}

}  // namespace

TEST(ThreeTerminals, KillingTheSimulatorEndsTheComponentAndTheRefereeWhichReportWhy) {
  ThreeTerminals run;
  ASSERT_TRUE(run.waitUntilRunning()) << run.output(kSimulator);
  run.kill(kSimulator);
  std::array<std::optional<int>, 3> codes;
  expectTheOthersEnd(run, kSimulator, codes);
  EXPECT_EQ(codes[kComponent], aula::process::kExitFailed);
  EXPECT_NE(run.output(kComponent).find("the simulator stopped (no SIM_CLOCK for 2 s of wall time): the component ends"),
            std::string::npos)
      << run.output(kComponent);
  EXPECT_EQ(codes[kReferee], aula::process::kExitFailed);
  const std::string report = readFile(run.report());
  EXPECT_NE(report.find("\"finished\": false"), std::string::npos) << report;
  EXPECT_NE(report.find("\"aborted\": \"the simulator stopped (no SIM_CLOCK for 2 s of wall time)\""), std::string::npos)
      << report;
  EXPECT_NE(run.output(kReferee).find("the run was aborted: the simulator stopped"), std::string::npos)
      << run.output(kReferee);
}

TEST(ThreeTerminals, KillingTheComponentEndsTheRunAndTheReportSaysTheComponentIsGone) {
  ThreeTerminals run;
  std::array<std::optional<int>, 3> codes;
  const std::string why = killAClient(run, kComponent, codes);
  EXPECT_EQ(codes[kReferee], aula::process::kExitFailed);
  const std::string report = readFile(run.report());
  EXPECT_NE(report.find("\"finished\": false"), std::string::npos) << report;
  EXPECT_NE(report.find("\"aborted\": \"the component 'teletaxi' is gone; the simulator ended the run: " + why + "\""),
            std::string::npos)
      << report;
}

TEST(ThreeTerminals, KillingTheRefereeEndsTheSimulatorAndTheComponentWhichSayWhy) {
  ThreeTerminals run;
  std::array<std::optional<int>, 3> codes;
  const std::string why = killAClient(run, kReferee, codes);
  EXPECT_EQ(codes[kComponent], aula::process::kExitFailed);
  EXPECT_NE(run.output(kComponent).find("the simulator ended the run: " + why + ": the component ends"), std::string::npos)
      << run.output(kComponent);
}
