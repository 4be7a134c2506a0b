// An exam under `aula grade` (issue 28), in C++ and in Python: a class of a quiet student and an
// attacker per attack, each a submission folder whose MyAlgorithm.cpp (exam_attack.hpp) or
// MyAlgorithm.py (python/exam_attack.py) attacks from inside execute(). Every attacker's own row
// says what it earned and why; the quiet student's row is what she gets when graded alone. The
// same reads and datagrams without the sandbox succeed, which shows the test can fail.
#include "test_support.hpp"

#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

namespace {
namespace fs = std::filesystem;
using namespace std::chrono_literals;
using aula::testing::readFile;

const std::string kAula = std::string(AULA_BIN_DIR) + "/aula";
constexpr const char* kShortRun = "--Vacuum.Referee.Duration=20";
// A flood is ended past 16 MB here (256 MB by default): the same rule, at less CPU for the machine.
constexpr const char* kOutputLimit = "--Component.Sandbox.Output=16";

// A UDP listener outside every run, on 0.0.0.0:port and in LCM's multicast group.
class Listener {
 public:
  Listener() {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    const int yes = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in any{};
    any.sin_family = AF_INET;
    any.sin_addr.s_addr = htonl(INADDR_ANY);
    EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&any), sizeof any), 0);
    socklen_t length = sizeof any;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&any), &length);
    port_ = ntohs(any.sin_port);
    ip_mreq group{};
    ::inet_pton(AF_INET, "239.255.76.67", &group.imr_multiaddr);
    group.imr_interface.s_addr = htonl(INADDR_LOOPBACK);
    ::setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &group, sizeof group);
  }
  ~Listener() { ::close(fd_); }
  int port() const { return port_; }
  int received() const {
    char buffer[2048];
    int count = 0;
    while (::recv(fd_, buffer, sizeof buffer, 0) > 0) ++count;
    return count;
  }

 private:
  int fd_ = -1;
  int port_ = 0;
};

std::map<std::string, std::map<std::string, std::string>> gradesOf(const std::string& csv_path) {
  std::ifstream in(csv_path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream head(line);
  for (std::string field; std::getline(head, field, ',');) header.push_back(field);
  std::map<std::string, std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    // Failures are the last fields but one: split the first columns, keep the rest whole.
    std::stringstream row(line);
    std::string student;
    std::getline(row, student, ',');
    rows[student]["line"] = line;
    for (size_t i = 1; i < header.size() && row.good(); ++i) std::getline(row, rows[student][header[i]], ',');
  }
  return rows;
}

// The attacks tried in each language: the C++ ones include exam_attack.hpp, the Python ones are
// python/exam_attack.py (sys.exit() in Python is an exception like any other, not the exit()
// that C++'s "exit" tries).
std::vector<std::string> attacksIn(const std::string& language) {
  std::vector<std::string> attacks = {"read", "udp", "memory", "fork", "privilege", "reference", "reexec", "_exit", "flood"};
  if (language == "cpp") attacks.insert(attacks.end(), {"exit", "find-reference"});
  return attacks;
}

// A student's folder whose algorithm tries `attack` ("none": a quiet student) in `language`.
void writeSubmission(const fs::path& folder, const std::string& attack, const std::string& language) {
  fs::create_directories(folder);
  if (language == "python") {
    std::ofstream(folder / "MyAlgorithm.py") << "AULA_EXAM_ATTACK = \"" << attack << "\"\n"
                                             << readFile(std::string(AULA_SOURCE_DIR) + "/tests/attacks/python/exam_attack.py");
    return;
  }
  std::ofstream(folder / "MyAlgorithm.cpp") << (attack == "reference" ? "#define AULA_EXAM_REFERENCE 1\n" : "")
                                            << "#define AULA_EXAM_ATTACK \"" << attack << "\"\n#include \""
                                            << AULA_SOURCE_DIR << "/tests/attacks/exam_attack.hpp\"\n";
}

int grade(const std::vector<std::string>& folders, const fs::path& out, const std::string& log) {
  std::vector<std::string> argv = {kAula, "grade", "vacuum"};
  argv.insert(argv.end(), folders.begin(), folders.end());
  argv.insert(argv.end(), {"--seeds=1", "--jobs=2", "--out=" + out.string(), kShortRun, kOutputLimit});
  aula::process::ChildProcess child(argv, log, log);
  return child.wait(300s).value_or(-1);
}

// Each `attempts` is said refused in `student`'s run log.
void expectRefused(const fs::path& out, const std::string& student, const std::vector<std::string>& attempts) {
  const std::string log = readFile((out / "runs" / student / "vacuum-seed1.log").string());
  for (const std::string& attempt : attempts) {
    EXPECT_NE(log.find("exam: " + attempt + ": refused"), std::string::npos) << student << ": " << attempt << "\n" << log;
  }
}

// The rows of the attackers whose attack ends their own run, each with its reason.
void expectEndedWithTheirReason(const std::map<std::string, std::map<std::string, std::string>>& rows,
                                const std::string& language) {
  auto line = [&](const std::string& student) { return rows.at(student).at("line"); };
  // The reference is out of a plugin's reach; reaching for it by name, or starting the component
  // again with it, ends the run, flagged.
  const std::string called = "the algorithm tried to call makeReferenceAlgorithm, the reference, which no student's algorithm may";
  for (const std::string student : {"reference", "find-reference", "reexec"}) {
    if (student == "find-reference" && language == "python") continue;
    const std::string why = student == "reexec" ? "the algorithm tried to run the component again with Vacuum.Algorithm=reference"
                                                : called;
    EXPECT_NE(line(student).find(why), std::string::npos) << line(student);
    EXPECT_EQ(rows.at(student).at("runs_tampered"), "1") << line(student);
    EXPECT_LT(std::stod(rows.at(student).at("median")), 1.0) << line(student);
  }
  if (language == "cpp") {
    EXPECT_NE(line("exit").find("the algorithm ended the component (exit() inside execute())"), std::string::npos)
        << line("exit");
  }
  // _exit(0) slips past the exit() watch: the launcher still says whose doing it was (not "silent").
  EXPECT_NE(line("_exit").find("the algorithm ended the component (exit code 0 in the middle of the run"), std::string::npos)
      << line("_exit");
  EXPECT_EQ(line("_exit").find("silent"), std::string::npos) << line("_exit");
  // The sandbox's limits, said as such (in Python too: not a MemoryError's traceback alone).
  EXPECT_NE(line("memory").find("the algorithm used more than 2048 MB of memory"), std::string::npos) << line("memory");
  EXPECT_NE(line("fork").find("the algorithm started more than 64 processes"), std::string::npos) << line("fork");
  EXPECT_NE(line("flood").find("the algorithm printed more than 16 MB (stdout and stderr)"), std::string::npos)
      << line("flood");
  EXPECT_EQ(rows.at("flood").at("runs_tampered"), "0") << line("flood");
}

// An exam in `language` (GetParam()): a quiet student and an attacker per attack, in one class.
class ExamIn : public ::testing::TestWithParam<std::string> {};

TEST_P(ExamIn, EachRunSeesOnlyItselfAndNothingLeavesIt) {
  const std::string language = GetParam();
  const fs::path dir = aula::testing::privateDir();
  const std::vector<std::string> attacks = attacksIn(language);
  writeSubmission(dir / "class" / "quiet", "none", language);
  for (const std::string& attack : attacks) writeSubmission(dir / "class" / attack, attack, language);
  fs::create_directories(dir / "teacher");
  fs::copy_file(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world", dir / "teacher" / "held_out.world");
  const std::string classmate = (dir / "class" / "quiet" / (language == "python" ? "MyAlgorithm.py" : "MyAlgorithm.cpp")).string();
  const std::vector<std::string> targets = {classmate, (dir / "out" / "manifest.json").string(),
                                            (dir / "teacher" / "held_out.world").string(), "/home"};
  std::string joined;
  for (const std::string& target : targets) joined += (joined.empty() ? "" : ":") + target;
  ::setenv("AULA_EXAM_READ", joined.c_str(), 1);
  ::setenv("AULA_EXAM_WRITE", (dir / "out" / "grades.csv").c_str(), 1);
  Listener listener;
  ::setenv("AULA_EXAM_PORT", std::to_string(listener.port()).c_str(), 1);

  // The quiet student alone: what her row must stay.
  ASSERT_EQ(grade({(dir / "class" / "quiet").string()}, dir / "alone", (dir / "alone.log").string()), 0)
      << readFile((dir / "alone.log").string());
  const auto alone = gradesOf((dir / "alone" / "grades.csv").string());

  std::vector<std::string> folders = {(dir / "class" / "quiet").string()};
  for (const std::string& attack : attacks) folders.push_back((dir / "class" / attack).string());
  ASSERT_EQ(grade(folders, dir / "out", (dir / "class.log").string()), 0) << readFile((dir / "class.log").string());
  const auto rows = gradesOf((dir / "out" / "grades.csv").string());
  ASSERT_EQ(rows.size(), attacks.size() + 1) << readFile((dir / "out" / "grades.csv").string());
  EXPECT_EQ(rows.at("quiet").at("line"), alone.at("quiet").at("line"));

  // Tries that fail and leave the run graded as its robot's behaviour earned.
  std::vector<std::string> reads;
  for (const std::string& target : targets) reads.push_back("read " + target);
  expectRefused(dir / "out", "read", reads);
  expectRefused(dir / "out", "privilege", {"unmount /proc", "remount / read-write", "make a user namespace",
                                          "write " + (dir / "out" / "grades.csv").string()});
  // The reference's plugin is not in a student's sandbox; its factory's name in the component is a
  // tripwire, which ends the run that calls it (below).
  expectRefused(dir / "out", language == "python" ? "reference" : "find-reference", {"load the reference's plugin"});
  // A datagram out of the run went nowhere, and flagged its run; the quiet student is not flagged.
  EXPECT_EQ(rows.at("udp").at("runs_tampered"), "1") << rows.at("udp").at("line");
  const std::string udp_result = readFile((dir / "out" / "runs" / "udp" / "vacuum-seed1.json").string());
  EXPECT_NE(udp_result.find("\"datagram to 127.0.0.1:" + std::to_string(listener.port()) + "\""), std::string::npos)
      << udp_result;
  EXPECT_EQ(rows.at("quiet").at("runs_tampered"), "0") << rows.at("quiet").at("line");
  // The tries that only an escape needs are refused and flagged, the mark left as earned.
  EXPECT_EQ(rows.at("privilege").at("runs_tampered"), "1") << rows.at("privilege").at("line");
  const std::string privilege_report = readFile((dir / "out" / "runs" / "privilege" / "vacuum-seed1.json").string());
  for (const char* call : {"\"umount2\"", "\"mount\"", "\"unshare\""}) {
    EXPECT_NE(privilege_report.find(call), std::string::npos) << call << "\n" << privilege_report;
  }
  EXPECT_NE(privilege_report.find("\"escape_attempts\""), std::string::npos) << privilege_report;
  for (const char* student : {"read", "udp", "privilege"}) {
    EXPECT_EQ(rows.at(student).at("runs_failed"), "0") << rows.at(student).at("line");
    EXPECT_EQ(rows.at(student).at("median"), alone.at("quiet").at("median")) << rows.at(student).at("line");
  }
  EXPECT_EQ(listener.received(), 0) << "a datagram left a graded run";
  const std::string udp_log = readFile((dir / "out" / "runs" / "udp" / "vacuum-seed1.log").string());
  EXPECT_NE(udp_log.find("exam: send to 127.0.0.1"), std::string::npos) << udp_log;
  // A flood of output ends that run (expectEndedWithTheirReason), its log capped (its head, its
  // tail and what was dropped).
  const fs::path flood_log = dir / "out" / "runs" / "flood" / "vacuum-seed1.log";
  EXPECT_LT(fs::file_size(flood_log), 1u << 20);
  EXPECT_NE(readFile(flood_log.string()).find("bytes of the component's output dropped here"), std::string::npos);
  expectEndedWithTheirReason(rows, language);

  // Without the sandbox the same reads and datagrams get through: the test can fail.
  for (const std::string attack : {"read", "udp", "find-reference"}) {
    if (attack == "find-reference" && language == "python") continue;
    const std::string log = (dir / ("open-" + attack + ".log")).string();
    const std::string algorithm = language == "python"  ? (dir / "class" / attack / "MyAlgorithm.py").string()
                                  : attack == "read"    ? AULA_EXAM_READ_PLUGIN
                                  : attack == "udp"     ? AULA_EXAM_UDP_PLUGIN
                                                        : AULA_EXAM_FIND_REFERENCE_PLUGIN;
    aula::process::ChildProcess run({kAula, "run", "vacuum", "--headless", "--algorithm=" + algorithm, kShortRun,
                                     "--lcm-url=" + aula::testing::privateLcmUrl()},
                                    log, log);
    EXPECT_EQ(run.wait(120s).value_or(-1), 0) << readFile(log);
  }
  const std::string open_log = readFile((dir / "open-read.log").string());
  EXPECT_NE(open_log.find("exam: read " + (dir / "teacher" / "held_out.world").string() + ": done"), std::string::npos)
      << open_log;
  EXPECT_GT(listener.received(), 0) << "without the sandbox the datagrams should have arrived";
  if (language == "cpp") {
    const std::string found = readFile((dir / "open-find-reference.log").string());
    EXPECT_NE(found.find("exam: load the reference's plugin: done"), std::string::npos) << found;
  }
  ::unsetenv("AULA_EXAM_READ");
  ::unsetenv("AULA_EXAM_WRITE");
  ::unsetenv("AULA_EXAM_PORT");
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Exam, ExamIn, ::testing::Values("cpp", "python"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// Without the sandbox, a student's detached children (their own session, SIGTERM blocked) do not
// outlive the run: the launcher is their subreaper and ends them.
TEST(Exam, DetachedChildrenDoNotOutliveTheRun) {
  const std::string dir = aula::testing::privateDir();
  const std::string log = dir + "/detach.log";
  const std::string length = "1000." + std::to_string(::getpid());  // this test's children, not another's
  ::setenv("AULA_EXAM_SLEEP", length.c_str(), 1);
  aula::process::ChildProcess run({kAula, "run", "vacuum", "--headless", std::string("--algorithm=") + AULA_EXAM_DETACH_PLUGIN,
                                   kShortRun, "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  EXPECT_EQ(run.wait(120s).value_or(-1), 0) << readFile(log);
  EXPECT_NE(readFile(log).find("exam: detach 20 children: done"), std::string::npos) << readFile(log);
  int left = 0;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream cmdline(entry.path() / "cmdline");
    std::string text((std::istreambuf_iterator<char>(cmdline)), std::istreambuf_iterator<char>());
    if (text == "sleep" + std::string(1, '\0') + length + std::string(1, '\0')) ++left;
  }
  ::unsetenv("AULA_EXAM_SLEEP");
  EXPECT_EQ(left, 0) << "detached children outlived the run";
  fs::remove_all(dir);
}

// What the files under `folder` take on a tmpfs (whole pages).
uint64_t pagesOf(const fs::path& folder) {
  uint64_t bytes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) bytes += (entry.file_size() + 4095) / 4096 * 4096;
  }
  return bytes;
}

// A full out folder ends the grade with that reason, keeps every finished run and gives the
// grades of those. The class is graded twice, one run at once with --record (a 120 s vacuum run
// records about 3 MB): first where there is room, to measure it, then on a tmpfs of its own
// (mounted in a private mount namespace, with a user namespace when not root) with room for the
// build, the first two runs and half of the third's recorded log; then, given room, it resumes.
TEST(Exam, AFullOutFolderEndsTheGradeAndKeepsTheFinishedRuns) {
  const fs::path dir = aula::testing::privateDir();
  const std::string bounce = readFile(std::string(AULA_SOURCE_DIR) + "/tests/data/plugins/vacuum_bounce.cpp");
  const std::vector<std::string> students = {"ana", "ben", "cat", "dan"};
  std::vector<std::string> argv = {kAula, "grade", "vacuum"};
  for (const std::string& student : students) {
    fs::create_directories(dir / "class" / student);
    std::ofstream(dir / "class" / student / "MyAlgorithm.cpp") << bounce;
    argv.push_back((dir / "class" / student).string());
  }
  argv.insert(argv.end(), {"--seeds=1", "--jobs=1", "--record", "--similarity=off", "--Vacuum.Referee.Duration=120"});
  auto gradeInto = [&](const std::vector<std::string>& before, const fs::path& out, const std::string& log) {
    std::vector<std::string> command = before;
    command.insert(command.end(), argv.begin(), argv.end());
    command.push_back("--out=" + out.string());
    aula::process::ChildProcess child(command, log, log);
    return child.wait(300s).value_or(-1);
  };
  ASSERT_EQ(gradeInto({}, dir / "roomy", (dir / "roomy.log").string()), 0) << readFile((dir / "roomy.log").string());
  const auto roomy = gradesOf((dir / "roomy" / "grades.csv").string());
  ASSERT_EQ(roomy.size(), 4u);
  const uint64_t third_log = fs::file_size(dir / "roomy" / "runs" / "cat" / "vacuum-seed1.lcmlog");
  ASSERT_GT(third_log, 2u << 20) << "the third run's recorded log must be what fills the folder";
  const uint64_t room = pagesOf(dir / "roomy" / "build") + fs::file_size(dir / "roomy" / "manifest.json") +
                        pagesOf(dir / "roomy" / "runs" / "ana") +
                        pagesOf(dir / "roomy" / "runs" / "ben") + third_log / 2 + 4096 * 8;

  // The out folder on a tmpfs of `room` bytes; what it holds is copied out when the grade ends.
  // Then the tmpfs is given room and the same command resumes (its exit code in resumed.code).
  const fs::path out = dir / "full", kept = dir / "kept", resumed = dir / "resumed";
  fs::create_directories(out);
  std::vector<std::string> unshare = {"unshare", "--mount", "--propagation", "private"};
  if (::geteuid() != 0) unshare.push_back("--map-root-user");
  unshare.insert(unshare.end(), {"sh", "-c",
                                 "mount -t tmpfs -o size=" + std::to_string(room) + " aula-full \"$0\" || exit 99; "
                                 "\"$@\"; code=$?; cp -r \"$0\" " + kept.string() + "; "
                                 "mount -o remount,size=64m aula-full \"$0\" || exit 99; echo '--- with room'; "
                                 "\"$@\"; echo $? > " + (dir / "resumed.code").string() + "; cp -r \"$0\" " + resumed.string() +
                                 "; exit $code",
                                 out.string()});
  const std::string log = (dir / "full.log").string();
  ASSERT_EQ(gradeInto(unshare, out, log), 1) << readFile(log);
  const std::string said = readFile(log).substr(0, readFile(log).find("--- with room"));
  EXPECT_NE(said.find("aula grade: stopped after 2 of 4 runs: "), std::string::npos) << said;
  EXPECT_NE(said.find("the run of cat on vacuum.world seed 1 ended without its report"), std::string::npos) << said;
  EXPECT_NE(said.find("No space left on device"), std::string::npos) << said;
  EXPECT_NE(said.find("hold the 2 finished runs only"), std::string::npos) << said;

  // The finished runs' grades, as where there was room; the others not graded, and nothing left
  // of the run the full folder stopped (no partial log, report or temporary file).
  const auto rows = gradesOf((kept / "grades.csv").string());
  ASSERT_EQ(rows.size(), 2u) << readFile((kept / "grades.csv").string());
  EXPECT_EQ(rows.at("ana").at("line"), roomy.at("ana").at("line"));
  EXPECT_EQ(rows.at("ben").at("line"), roomy.at("ben").at("line"));
  EXPECT_TRUE(fs::exists(kept / "runs" / "ben" / "vacuum-seed1.lcmlog"));
  EXPECT_TRUE(fs::is_empty(kept / "runs" / "cat"));
  EXPECT_FALSE(fs::exists(kept / "runs" / "dan"));
  for (const auto& entry : fs::recursive_directory_iterator(kept)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
  }
  // With room, the same command does the two runs left, and the class's grades are as if the
  // folder had never been full.
  const std::string again = readFile(log).substr(said.size());
  EXPECT_EQ(readFile((dir / "resumed.code").string()), "0\n") << again;
  EXPECT_NE(again.find("2 runs already done (same plugin, world, seed and settings): skipped"), std::string::npos) << again;
  EXPECT_EQ(readFile((resumed / "grades.csv").string()), readFile((dir / "roomy" / "grades.csv").string()));
  fs::remove_all(dir);
}

// Two sandboxed runs at once on the same LCM port: each its own network, so both grade as alone.
TEST(Exam, TwoSandboxedRunsOnOnePortGradeAsAlone) {
  const std::string dir = aula::testing::privateDir();
  const std::string url = "--lcm-url=udpm://239.255.76.67:" + std::to_string(aula::testing::freeUdpPort()) + "?ttl=0";
  std::vector<std::unique_ptr<aula::process::ChildProcess>> runs;
  for (int i = 0; i < 2; ++i) {
    const std::string log = dir + "/run" + std::to_string(i) + ".log";
    runs.push_back(std::make_unique<aula::process::ChildProcess>(
        std::vector<std::string>{kAula, "run", "vacuum", "--headless", "--sandbox", "--algorithm=reference", "--seed=4",
                                 kShortRun, url, "--cpu=any", "--report=" + dir + "/run" + std::to_string(i) + ".json"},
        log, log));
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(runs[i]->wait(120s).value_or(-1), 0) << readFile(dir + "/run" + std::to_string(i) + ".log");
  }
  const std::string first = readFile(dir + "/run0.json"), second = readFile(dir + "/run1.json");
  EXPECT_NE(first.find("\"finished\": true"), std::string::npos) << first;
  EXPECT_NE(first.find("\"isolation\": \"full\""), std::string::npos) << first;
  EXPECT_EQ(first, second);
  fs::remove_all(dir);
}

}  // namespace
