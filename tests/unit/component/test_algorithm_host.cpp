// The algorithm host's hot reload on a real plugin file: a new build is noticed, a build that
// cannot be used becomes the fault (nothing runs, nothing crashes) and is not offered again,
// and the next good build runs a fresh algorithm.
#include <aula/component/algorithm_host.hpp>
#include <aula/config/paths.hpp>
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <memory>
#include <regex>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using aula::component::AlgorithmHost;
using aula::component::Motors;
using aula::vacuum::VacuumAlgorithm;
using aula::component::CallKind;

namespace {

// The default budgets, with execute() given `cpu_s` of CPU time (0: no limit).
aula::component::AlgorithmBudgets withExecuteBudget(double cpu_s) {
  aula::component::AlgorithmBudgets budgets;
  budgets.execute.cpu_s = cpu_s;
  return budgets;
}

// Replaces `to` and moves its modification time on (file systems keep it to the nanosecond,
// but two writes in one test can still share a tick).
void replaceFile(const fs::path& from, const fs::path& to) {
  const auto before = fs::exists(to) ? fs::last_write_time(to) : fs::file_time_type::min();
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  fs::last_write_time(to, std::max(fs::last_write_time(to), before + std::chrono::seconds(1)));
}

// A vacuum's devices and API, owned by the calls too: one could outlive the test.
struct Devices {
  aula::component::Pose3d pose;
  aula::vacuum::YawSensor yaw{pose};
  aula::component::Laser laser;
  aula::component::Bumper bumper;
  Motors motors{1.0, 1.0};
  aula::component::Belief belief;
  aula::vacuum::VacuumApi api{yaw, laser, bumper, motors, belief, 0.08};
};

class AlgorithmHostReload : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("aula-host-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    ::setenv("XDG_CACHE_HOME", (dir_ / "cache").c_str(), 1);
    plugin_ = dir_ / "libmy_algorithm.so";
    replaceFile(AULA_PLUGIN_DOES_NOTHING, plugin_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_, plugin_;
};

}  // namespace

TEST_F(AlgorithmHostReload, ABadBuildBecomesTheFaultAndTheNextGoodOneRuns) {
  Motors motors(1.0, 1.0);
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", plugin_.string(), motors, withExecuteBudget(0));
  auto run = [&] { return host.call(1, "execute()", CallKind::Execute, [](VacuumAlgorithm&) {}); };
  EXPECT_TRUE(run());
  EXPECT_FALSE(host.pluginChanged());

  {  // The student's build broke: not a shared library any more.
    std::ofstream(dir_ / "broken.so") << "not an ELF file";
    replaceFile(dir_ / "broken.so", plugin_);
  }
  EXPECT_TRUE(host.pluginChanged());
  EXPECT_FALSE(host.reload());
  EXPECT_NE(host.fault().find("reloading libmy_algorithm.so failed"), std::string::npos) << host.fault();
  EXPECT_NE(host.fault().find("not a shared library"), std::string::npos) << host.fault();
  EXPECT_FALSE(run());                  // nothing loaded, nothing runs
  EXPECT_FALSE(host.pluginChanged());   // the refused build is not offered again
  EXPECT_EQ(host.pluginPath(), fs::absolute(plugin_).lexically_normal().string());

  replaceFile(AULA_PLUGIN_DOES_NOTHING, plugin_);  // fixed and rebuilt
  EXPECT_TRUE(host.pluginChanged());
  EXPECT_TRUE(host.reload());
  EXPECT_EQ(host.fault(), "");
  EXPECT_TRUE(run());
  EXPECT_NE(host.label().find("libmy_algorithm.so (built "), std::string::npos) << host.label();
}

// A built-in (the reference) is a plugin of its own under <lib>/aula/references: named by its
// name, never offered as a new build, and reloading it makes a fresh algorithm that runs.
TEST(AlgorithmHost, ABuiltInIsAPluginOfItsOwnNamedByItsName) {
  auto devices = std::make_shared<Devices>();
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", "reference", devices->motors, withExecuteBudget(0));
  EXPECT_EQ(host.pluginPath(), aula::config::builtinAlgorithmPath("vacuum", "reference"));
  EXPECT_NE(host.pluginPath().find("/lib/aula/references/libaula_vacuum_reference.so"), std::string::npos) << host.pluginPath();
  EXPECT_EQ(host.name(), "reference");
  EXPECT_EQ(host.label(), "reference");
  EXPECT_FALSE(host.isPlugin());
  EXPECT_FALSE(host.pluginChanged());
  auto run = [&] { return host.call(1, "execute()", CallKind::Execute, [devices](VacuumAlgorithm& a) { a.execute(devices->api); }); };
  EXPECT_TRUE(run()) << host.fault();
  EXPECT_TRUE(host.reload());
  EXPECT_TRUE(run()) << host.fault();
  // An unknown name says what it looked for.
  try {
    AlgorithmHost<VacuumAlgorithm> unknown("test", "vacuum", "oracle", devices->motors, withExecuteBudget(0));
    ADD_FAILURE() << "an unknown built-in was loaded";
  } catch (const aula::component::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("not a built-in algorithm of vacuum (no "), std::string::npos) << e.what();
  }
}

// With windows (containHangs), a MyAlgorithm.py stuck in a loop is interrupted inside Python:
// the call returns as a fault naming the loop's line, the algorithm is not abandoned (no hang),
// and a fixed file runs after Reload.
TEST_F(AlgorithmHostReload, APythonLoopWithWindowsIsInterruptedAtItsLineAndReloadWorks) {
  auto devices = std::make_shared<Devices>();  // owned by the calls too: one could outlive the test
  const fs::path file = dir_ / "MyAlgorithm.py";
  replaceFile(std::string(AULA_TEST_DATA_DIR) + "/python/endless_loop/MyAlgorithm.py", file);
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", file.string(), devices->motors, withExecuteBudget(0.5));
  host.containHangs();
  auto run = [&] { return host.call(1, "execute()", CallKind::Execute, [devices](VacuumAlgorithm& a) { a.execute(devices->api); }); };
  for (int call = 1; call <= 5; ++call) EXPECT_TRUE(run()) << call << ": " << host.fault();
  EXPECT_FALSE(run());  // the 6th call loops
  EXPECT_FALSE(host.hung());
  EXPECT_TRUE(std::regex_search(host.fault(), std::regex("^MyAlgorithm\\.py:1[12]: execute\\(\\) used more than 0\\.5 s of "
                                                         "CPU time \\(an endless loop\\?\\) \\(Component\\.ExecuteBudget\\): "
                                                         "interrupted here")))
      << host.fault();
  EXPECT_NE(host.label().find("MyAlgorithm.py (saved "), std::string::npos) << host.label();

  replaceFile(std::string(AULA_TEST_DATA_DIR) + "/python/nan_commands/MyAlgorithm.py", file);  // "fixed"
  EXPECT_TRUE(host.pluginChanged());
  EXPECT_TRUE(host.reload()) << host.fault();
  EXPECT_TRUE(run()) << host.fault();
  EXPECT_EQ(devices->motors.nonFiniteV(), 1);  // the new file ran: it sends NaN
}

// With windows (containHangs), a program in RoboticsAcademy's shape paused in its loop (a greenlet
// of the AlgorithmThread) is ended at Reload by that thread, before reload() returns: its
// `finally` has run there, and the fresh program runs. Ending it throws inside greenlet (C++),
// on the greenlet's stack: a throw site kept there (backtrace()) crashed the process (SIGSEGV;
// gui.RoboticsAcademyProgramWithWindowsReloadsAndParks on Debian 13, at the next call).
TEST_F(AlgorithmHostReload, AProgramPausedWithWindowsIsEndedOnItsOwnThreadAtReload) {
  auto devices = std::make_shared<Devices>();
  const fs::path file = dir_ / "MyAlgorithm.py";
  std::ofstream(file) << "import threading, time\n"
                         "open('" << (dir_ / "ran").string() << "', 'a').write(str(threading.get_ident()) + '\\n')\n"
                         "try:\n"
                         "    while True:\n"
                         "        time.sleep(0.1)  # the sim clock stands still here: paused for good\n"
                         "finally:\n"
                         "    open('" << (dir_ / "ended").string() << "', 'a').write(str(threading.get_ident()) + '\\n')\n";
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", file.string(), devices->motors, withExecuteBudget(5));
  host.containHangs();
  auto run = [&] { return host.call(1, "execute()", CallKind::Execute, [devices](VacuumAlgorithm& a) { a.execute(devices->api); }); };
  auto lines = [](const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  };
  for (int reload = 1; reload <= 3; ++reload) {
    for (int call = 1; call <= 3; ++call) EXPECT_TRUE(run()) << reload << "." << call << ": " << host.fault();
    EXPECT_TRUE(host.reload()) << host.fault();
    const auto ran = lines(dir_ / "ran"), ended = lines(dir_ / "ended");
    ASSERT_EQ(ran.size(), static_cast<size_t>(reload));
    ASSERT_EQ(ended.size(), static_cast<size_t>(reload)) << "the paused program was not ended at Reload";
    EXPECT_EQ(ended.back(), ran.back()) << "the program was ended on another thread than its own";
  }
  EXPECT_TRUE(run()) << host.fault();
  EXPECT_EQ(lines(dir_ / "ran").size(), 4u);
}

namespace {

int lineOf(const std::string& file, const std::string& text) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(text) != std::string::npos) return n;
  }
  return 0;
}


}  // namespace

// With windows (containHangs), a C++ algorithm that crashes inside execute() does not end the
// process: the call comes back as a fault naming the student's line (from the plugin's source,
// not a constant), and a fixed build runs after Reload.
TEST_F(AlgorithmHostReload, ACrashWithWindowsBecomesTheFaultAtItsLineAndReloadWorks) {
  replaceFile(AULA_PLUGIN_SEGFAULT, plugin_);
  auto devices = std::make_shared<Devices>();
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", plugin_.string(), devices->motors, withExecuteBudget(5));
  host.containHangs();
  auto run = [&] { return host.call(1, "execute()", CallKind::Execute, [devices](VacuumAlgorithm& a) { a.execute(devices->api); }); };
  for (int call = 1; call <= 5; ++call) EXPECT_TRUE(run()) << call << ": " << host.fault();
  EXPECT_FALSE(run());  // the 6th call writes through a null pointer
  const int line = lineOf(std::string(AULA_TEST_DATA_DIR) + "/plugins/segfault.cpp", "*nowhere = calls_;");
  EXPECT_EQ(host.fault(), "execute() crashed (SIGSEGV) at segfault.cpp:" + std::to_string(line) + " (Segfault::execute)");
  EXPECT_TRUE(host.crashed());
  EXPECT_FALSE(host.hung());
  EXPECT_FALSE(run());  // halted until a reload

  replaceFile(AULA_PLUGIN_DOES_NOTHING, plugin_);  // fixed and rebuilt
  EXPECT_TRUE(host.reload()) << host.fault();
  EXPECT_FALSE(host.crashed());
  for (int call = 1; call <= 10; ++call) EXPECT_TRUE(run()) << call << ": " << host.fault();
}

// A stack overflow inside the call is caught too (the handler runs on an alternate stack).
TEST(AlgorithmHost, AStackOverflowWithWindowsBecomesTheFault) {
  Motors motors(1.0, 1.0);
  AlgorithmHost<VacuumAlgorithm> host("test", "vacuum", AULA_PLUGIN_STACK_OVERFLOW, motors, withExecuteBudget(5));
  host.containHangs();
  auto devices = std::make_shared<Devices>();
  EXPECT_FALSE(host.call(1, "execute()", CallKind::Execute, [devices](VacuumAlgorithm& a) { a.execute(devices->api); }));
  EXPECT_EQ(host.fault().rfind("execute() crashed (SIGSEGV)", 0), 0u) << host.fault();
  EXPECT_TRUE(host.reload());  // the crashed algorithm is left as it was, a fresh one made
  EXPECT_EQ(host.fault(), "");
}
