// A run recorded with `aula run --record` in LCM's log format, graded again from the log alone
// with `aula regrade`: the report must be byte-identical to the live run's (the referee depends
// only on what the log holds), and the stock lcm-logplayer must play the log.
#include "test_support.hpp"

#include <aula/lcm/log_replay.hpp>
#include <aula/process/child_process.hpp>

#include <aula/pose3d_t.hpp>
#include <aula/sim_clock_t.hpp>
#include <aula/lcm/bus.hpp>
#include <lcm/lcm-cpp.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <cmath>
#include <random>

using namespace std::chrono_literals;
using aula::testing::readFile;

namespace {

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";

// Another private port for lcm-logplayer, away from the run's.
std::string otherPrivateUrl() {
  return "udpm://239.255.76.67:" + std::to_string(aula::testing::freeUdpPort()) + "?ttl=0";
}

// Events per channel, read with LCM's own log reader.
std::map<std::string, int> eventsPerChannel(const std::string& path) {
  std::map<std::string, int> count;
  lcm::LogFile log(path, "r");
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) ++count[e->channel];
  return count;
}

struct Graded {
  std::string live, regraded;  // the two reports
  std::string log_path;
};

Graded recordAndRegrade(const std::string& tag, const std::vector<std::string>& run_args) {
  const std::string dir = aula::testing::privateDir();
  Graded g;
  g.log_path = dir + "/" + tag + ".lcmlog";
  const std::string live = dir + "/live.json", regraded = dir + "/regraded.json", out = dir + "/out.txt";
  std::vector<std::string> args = {kAula, "run"};
  args.insert(args.end(), run_args.begin(), run_args.end());
  args.insert(args.end(), {"--headless", "--record=" + g.log_path, "--report=" + live,
                           "--lcm-url=" + aula::testing::privateLcmUrl()});
  aula::process::ChildProcess run(args, out, out);
  const auto code = run.wait(200s);
  EXPECT_EQ(code.value_or(-1), 0) << readFile(out);
  aula::process::ChildProcess regrade({kAula, "regrade", g.log_path, "--report=" + regraded}, out + "2", out + "2");
  EXPECT_EQ(regrade.wait(100s).value_or(-1), 0) << readFile(out + "2");
  g.live = readFile(live);
  g.regraded = readFile(regraded);
  EXPECT_FALSE(g.live.empty()) << readFile(out);
  EXPECT_NE(readFile(out + "2").find("mark"), std::string::npos) << "regrade prints the summary\n" << readFile(out + "2");
  return g;
}

// The stock player plays the whole file (quickly, onto a port nobody listens to): one line per
// event with -v, as many as LCM's reader finds, the run's record first.
void expectLcmLogplayerPlays(const std::string& path) {
  const std::string out = path + ".player.txt";
  aula::process::ChildProcess player({"lcm-logplayer", "-v", "--speed=100", "--lcm-url=" + otherPrivateUrl(), path},
                                     out, out);
  EXPECT_EQ(player.wait(60s).value_or(-1), 0) << readFile(out);
  const std::string played = readFile(out);
  int lines = 0;
  for (size_t at = played.find(" Channel "); at != std::string::npos; at = played.find(" Channel ", at + 1)) ++lines;
  int events = 0;
  for (const auto& [channel, count] : eventsPerChannel(path)) events += count;
  EXPECT_EQ(lines, events);
  EXPECT_NE(played.find(" Channel AULA_RUN "), std::string::npos) << played.substr(0, 500);
}

}  // namespace

TEST(RecordRegrade, VacuumReportIsByteIdentical) {
  const Graded g = recordAndRegrade("vacuum", {"vacuum", "--algorithm=reference", "--seed=3", "--Vacuum.Referee.Duration=60"});
  EXPECT_EQ(g.live, g.regraded);
  EXPECT_DOUBLE_EQ(aula::testing::jsonNumber(g.regraded, "sim_time_s"), 60.0) << g.regraded;
  const auto events = eventsPerChannel(g.log_path);
  EXPECT_EQ(events.count(aula::lcmbus::kRunChannel), 1u);
  // 50 Hz for 60 s, both ends: the log holds every pose the referee counted.
  EXPECT_GE(events.count("ROOMBA_POSE") ? events.at("ROOMBA_POSE") : 0, 3001);
  const aula::run_record_t record = aula::lcmbus::readRunRecord(g.log_path);
  EXPECT_EQ(record.exercise, "vacuum");
  EXPECT_EQ(record.seed, 3);
  EXPECT_EQ(record.world, "vacuum.world");
  EXPECT_NE(std::find(record.settings.begin(), record.settings.end(), "Vacuum.Referee.Duration=60"), record.settings.end());
  expectLcmLogplayerPlays(g.log_path);
}

// aula-sim --commands: a lone simulator, driven by the motors commands the log recorded (each at
// the tick it answered), makes the run's motions: every recorded pose again, exactly (the
// baseline of bench/exercise_overhead.sh).
TEST(RecordRegrade, ALoneSimulatorDrivenByTheRecordedCommandsRetracesTheRun) {
  const Graded g = recordAndRegrade("commands", {"vacuum", "--algorithm=reference", "--seed=2", "--Vacuum.Referee.Duration=20"});
  std::map<int64_t, aula::pose3d_t> recorded;
  {
    lcm::LogFile log(g.log_path, "r");
    for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
      aula::pose3d_t pose;
      if (e->channel == "ROOMBA_POSE" && pose.decode(e->data, 0, e->datalen) > 0 && pose.utime <= 20'000'000) {
        recorded[pose.utime] = pose;
      }
    }
  }
  ASSERT_GE(recorded.size(), 1001u);
  const std::string url = aula::testing::privateLcmUrl();
  auto bus = aula::lcmbus::openBus(url);  // listening before the simulator starts
  std::map<int64_t, aula::pose3d_t> retraced;
  struct Collect {
    std::map<int64_t, aula::pose3d_t>* poses;
    void on(const lcm::ReceiveBuffer*, const std::string&, const aula::pose3d_t* m) { (*poses)[m->utime] = *m; }
  } collect{&retraced};
  bus->subscribe("ROOMBA_POSE", &Collect::on, &collect);
  const std::string out = g.log_path + ".sim.txt";
  aula::process::ChildProcess sim({AULA_SIM_PATH, std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world", "--rtf=20",
                                   "--duration=20", "--seed=2", "--Simulator.PhysicsStep=0.01",  // the vacuum exercise's step, as aula run gives it
                                   "--lcm-url=" + url, "--commands=" + g.log_path},
                                  out, out);
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  std::optional<int> code;
  while (!(code = sim.poll()) && std::chrono::steady_clock::now() < deadline) bus->handleTimeout(20);
  while (bus->handleTimeout(50) > 0) {
  }
  EXPECT_EQ(code.value_or(-1), 0) << readFile(out);
  int compared = 0, moved_m = 0;
  for (const auto& [utime, pose] : recorded) {
    const auto again = retraced.find(utime);
    ASSERT_NE(again, retraced.end()) << "no pose at " << utime << " us";
    EXPECT_EQ(again->second.x, pose.x) << utime;
    EXPECT_EQ(again->second.y, pose.y) << utime;
    EXPECT_EQ(again->second.yaw, pose.yaw) << utime;
    ++compared;
    moved_m = std::max(moved_m, static_cast<int>(std::hypot(pose.x - recorded.begin()->second.x, pose.y - recorded.begin()->second.y)));
  }
  EXPECT_EQ(compared, static_cast<int>(recorded.size()));
  EXPECT_GE(moved_m, 1) << "the recorded robot went somewhere, so the commands mattered";
}

TEST(RecordRegrade, TeleTaxiReportIsByteIdentical) {
  const Graded g = recordAndRegrade("teletaxi", {"teletaxi", "--algorithm=reference", "--seed=4"});
  EXPECT_EQ(g.live, g.regraded);
  EXPECT_NE(g.regraded.find("\"reached\": true"), std::string::npos) << g.regraded;
  expectLcmLogplayerPlays(g.log_path);
}

TEST(RecordRegrade, AutoparkReportIsByteIdentical) {
  const Graded g = recordAndRegrade("autopark", {"autopark", "--algorithm=reactive", "--seed=5"});
  EXPECT_EQ(g.live, g.regraded);
  EXPECT_NE(g.regraded.find("\"exercise\": \"autopark\""), std::string::npos) << g.regraded;
  expectLcmLogplayerPlays(g.log_path);
}

// A log cut short (a run recorded in part): the referee grades what it holds and says the
// episode did not end.
TEST(RecordRegrade, ALogCutShortIsNotAFinishedRun) {
  const Graded g = recordAndRegrade("cut", {"vacuum", "--algorithm=reference", "--seed=3", "--Vacuum.Referee.Duration=20"});
  EXPECT_EQ(g.live, g.regraded);
  // Keep the events before 10 s of sim time (half the episode). Cut by sim time, not by event
  // count: after the episode the simulator runs on until it is stopped, more or less long
  // depending on the machine's load, so half the events may hold the whole episode.
  const std::string cut = g.log_path + ".cut";
  {
    lcm::LogFile in(g.log_path, "r"), out(cut, "w");
    for (const lcm::LogEvent* e = in.readNextEvent(); e != nullptr; e = in.readNextEvent()) {
      if (e->channel == "SIM_CLOCK") {
        aula::sim_clock_t tick;
        if (tick.decode(e->data, 0, e->datalen) > 0 && tick.utime >= 10'000'000) break;
      }
      lcm::LogEvent copy = *e;
      out.writeEvent(&copy);
    }
  }
  const std::string report = cut + ".json", text = cut + ".txt";
  // A cut log is not what was signed: regraded only when told so; without its key it is only
  // "not signed", with its key beside it, it was cut.
  aula::process::ChildProcess refused({kAula, "regrade", cut, "--report=" + report}, text, text);
  EXPECT_EQ(refused.wait(60s).value_or(-1), 2) << readFile(text);
  EXPECT_NE(readFile(text).find("it is not signed"), std::string::npos) << readFile(text);
  std::filesystem::copy_file(g.log_path + ".key", cut + ".key", std::filesystem::copy_options::overwrite_existing);
  aula::process::ChildProcess said({kAula, "regrade", cut, "--report=" + report}, text, text);
  EXPECT_EQ(said.wait(60s).value_or(-1), 2) << readFile(text);
  EXPECT_NE(readFile(text).find("it was cut or damaged after it was recorded"), std::string::npos) << readFile(text);
  aula::process::ChildProcess regrade({kAula, "regrade", cut, "--unsigned", "--report=" + report}, text, text);
  EXPECT_EQ(regrade.wait(60s).value_or(-1), 1) << readFile(text);
  EXPECT_NE(readFile(text).find("the log ends before the end of the episode"), std::string::npos) << readFile(text);
  EXPECT_NE(readFile(report).find("\"finished\": false"), std::string::npos) << readFile(report);
}

// A graded run's log is signed: untouched it is regraded, with one pose changed it is refused
// (naming the events that changed) unless told --unsigned.
TEST(RecordRegrade, ATamperedLogIsRefusedTheUntouchedOneAccepted) {
  const Graded g = recordAndRegrade("signed", {"vacuum", "--algorithm=reference", "--seed=2", "--Vacuum.Referee.Duration=20"});
  EXPECT_EQ(g.live, g.regraded);
  const std::string out = g.log_path + ".check.txt";
  aula::process::ChildProcess check({kAula, "regrade", g.log_path}, out, out);
  EXPECT_EQ(check.wait(60s).value_or(-1), 0) << readFile(out);
  EXPECT_NE(readFile(out).find("signed and unaltered"), std::string::npos) << readFile(out);
  // One pose moved by a millimetre's worth of bytes, the rest as it was.
  const std::string tampered = g.log_path + ".tampered";
  {
    lcm::LogFile in(g.log_path, "r"), copy(tampered, "w");
    int poses = 0;
    for (const lcm::LogEvent* e = in.readNextEvent(); e != nullptr; e = in.readNextEvent()) {
      lcm::LogEvent event = *e;
      std::vector<uint8_t> bytes(static_cast<const uint8_t*>(e->data), static_cast<const uint8_t*>(e->data) + e->datalen);
      if (e->channel == "ROOMBA_POSE" && ++poses == 500) bytes[bytes.size() / 2] ^= 0x01;
      event.data = bytes.data();
      copy.writeEvent(&event);
    }
  }
  std::filesystem::copy_file(g.log_path + ".key", tampered + ".key");
  aula::process::ChildProcess refused({kAula, "regrade", tampered}, out, out);
  EXPECT_EQ(refused.wait(60s).value_or(-1), 2) << readFile(out);
  EXPECT_NE(readFile(out).find("altered after it was signed: events "), std::string::npos) << readFile(out);
  aula::process::ChildProcess anyway({kAula, "regrade", tampered, "--unsigned"}, out, out);
  EXPECT_NE(anyway.wait(60s).value_or(-1), 2) << readFile(out);
}

TEST(RecordRegrade, RefusesWhatIsNotARecordedRun) {
  const std::string dir = aula::testing::privateDir();
  const std::string text = dir + "/not_a_log.lcmlog", out = dir + "/out.txt";
  { std::ofstream(text) << "hello, this is not an LCM log\n"; }
  const std::string foreign = dir + "/foreign.lcmlog";  // a log, but not one `aula run` recorded
  {
    lcm::LogFile log(foreign, "w");
    char byte = 1;
    lcm::LogEvent event{0, 0, "SOMEONE_ELSES", 1, &byte};
    log.writeEvent(&event);
  }
  for (const auto& [file, says] : std::vector<std::pair<std::string, std::string>>{
           {dir + "/missing.lcmlog", "no such file"}, {text, "not an LCM log"}, {foreign, "not recorded by"}}) {
    aula::process::ChildProcess regrade({kAula, "regrade", file}, out, out);
    EXPECT_EQ(regrade.wait(20s).value_or(-1), 2) << readFile(out);
    EXPECT_NE(readFile(out).find(says), std::string::npos) << readFile(out);
    EXPECT_NE(readFile(out).find(file), std::string::npos) << "names the file\n" << readFile(out);
  }
  // A record into a folder that does not exist: refused before anything starts.
  const std::string missing_folder = dir + "/no/such/folder";
  aula::process::ChildProcess run({kAula, "run", "vacuum", "--headless", "--record=" + missing_folder + "/run.lcmlog",
                                   "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  out, out);
  EXPECT_EQ(run.wait(20s).value_or(-1), 2) << readFile(out);
  EXPECT_NE(readFile(out).find(missing_folder), std::string::npos) << readFile(out);
  EXPECT_NE(readFile(out).find("does not exist"), std::string::npos) << readFile(out);
}
