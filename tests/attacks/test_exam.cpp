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
#include <sys/syscall.h>
#include <zlib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
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
  std::vector<std::string> attacks = {"read",   "udp",   "memory",  "fork",     "privilege",     "reference",
                                      "reexec", "_exit", "flood",   "keyring",  "io_uring",      "shared-memory",
                                      "world-in-exception", "fork-memory"};
  if (language == "cpp") attacks.insert(attacks.end(), {"exit", "find-reference"});
  return attacks;
}

// What the attacks are told, written into each submission (the sandbox clears the environment).
struct Targets {
  std::string read;   // files to read, colon-separated
  std::string write;  // a file to write
  int port = 9;       // a listener's port outside the run
};

// A student's folder whose algorithm tries `attack` ("none": a quiet student) in `language`.
void writeSubmission(const fs::path& folder, const std::string& attack, const std::string& language,
                     const Targets& targets = {}) {
  fs::create_directories(folder);
  if (language == "python") {
    std::ofstream(folder / "MyAlgorithm.py") << "AULA_EXAM_ATTACK = \"" << attack << "\"\nAULA_EXAM_READ = \"" << targets.read
                                             << "\"\nAULA_EXAM_WRITE = \"" << targets.write << "\"\nAULA_EXAM_PORT = \""
                                             << targets.port << "\"\n"
                                             << readFile(std::string(AULA_SOURCE_DIR) + "/tests/attacks/python/exam_attack.py");
    return;
  }
  // The attack's code beside it, a header of the student's own (the build sees only the folder).
  fs::copy_file(std::string(AULA_SOURCE_DIR) + "/tests/attacks/exam_attack.hpp", folder / "exam_attack.hpp",
                fs::copy_options::overwrite_existing);
  std::ofstream(folder / "MyAlgorithm.cpp") << (attack == "reference" ? "#define AULA_EXAM_REFERENCE 1\n" : "")
                                            << "#define AULA_EXAM_ATTACK \"" << attack << "\"\n"
                                            << "#define AULA_EXAM_READ_LIST \"" << targets.read << "\"\n"
                                            << "#define AULA_EXAM_WRITE_PATH \"" << targets.write << "\"\n"
                                            << "#define AULA_EXAM_PORT_NUMBER \"" << targets.port << "\"\n"
                                            << "#include \"exam_attack.hpp\"\n";
}

int grade(const std::vector<std::string>& folders, const fs::path& out, const std::string& log,
          const std::vector<std::string>& more = {}) {
  std::vector<std::string> argv = {kAula, "grade", "vacuum"};
  argv.insert(argv.end(), folders.begin(), folders.end());
  // The fixed rubric: a class's marks, not a 20 s grade's own calibration, are what is compared.
  argv.insert(argv.end(), {"--seeds=1", "--jobs=2", "--out=" + out.string(), kShortRun, kOutputLimit, "--calibration-seeds=off"});
  argv.insert(argv.end(), more.begin(), more.end());
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
  // The reference is out of a plugin's reach; reaching for it by name, or starting its own program
  // again (the algorithm's process, which has no socket to a component then), ends the run, flagged.
  const std::string called = "the algorithm tried to call makeReferenceAlgorithm, the reference, which no student's algorithm may";
  for (const std::string student : {"reference", "find-reference", "reexec"}) {
    if (student == "find-reference" && language == "python") continue;
    const std::string why = student == "reexec" ? "the algorithm tried to run the algorithm's process again"
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

// `attack` run without the sandbox (`aula run`, no --sandbox) and inside the component (no process
// of its own), told its targets through the environment: its log (dir/open-<attack>.log).
std::string runWithoutSandbox(const fs::path& dir, const std::string& attack, const std::string& language) {
  const std::string log = (dir / ("open-" + attack + ".log")).string();
  const std::string algorithm = language == "python" ? (dir / "class" / attack / "MyAlgorithm.py").string()
                                                     : std::string(AULA_EXAM_PLUGIN_DIR) + "/libaula_test_exam_" + attack + ".so";
  // Writing 3 GB takes longer than one execute() may (2 s), or than the lockstep waits for the
  // component (5 s), on a loaded machine: neither applies here.
  aula::process::ChildProcess run({kAula, "run", "vacuum", "--headless", "--algorithm=" + algorithm, kShortRun,
                                   "--Component.OwnProcess=off", "--Component.ExecuteBudget=0",
                                   "--Simulator.Lockstep.DropAfterMs=120000",
                                   "--lcm-url=" + aula::testing::privateLcmUrl()},
                                  log, log);
  const int code = run.wait(120s).value_or(-1);
  // A run that throws ends with its fault; one that writes gigabytes may stall its lockstep
  // (components' own watch on SIM_CLOCK) on a loaded machine: what it said is what counts.
  const bool heavy = attack == "world-in-exception" || attack == "shared-memory" || attack == "fork-memory";
  EXPECT_TRUE(code == 0 || heavy) << readFile(log);
  return readFile(log);
}

// What a teacher's session holds that no run may see: a variable of the environment, and a key of
// the session keyring (added by addSessionKey).
constexpr const char* kTeacherToken = "teacher-token-4711";
constexpr const char* kTeacherKey = "teacher-session-key-4711";

// Adds "aula-exam-secret" (kTeacherKey) to this process's session keyring, which the runs it
// starts inherit. False where the system allows no keyring (a container's filter).
bool addSessionKey() {
  const long key = ::syscall(SYS_add_key, "user", "aula-exam-secret", kTeacherKey, std::strlen(kTeacherKey),
                             -3 /* KEY_SPEC_SESSION_KEYRING */);
  return key >= 0;
}

// A page's run data block (zlib's deflate in base64, run_page.cpp) as the text it packs.
std::string unpackedRunData(const std::string& html) {
  const std::string open = "type='application/octet-stream' id='run'>";
  const size_t begin = html.find(open);
  if (begin == std::string::npos) return "";
  const size_t from = begin + open.size(), to = html.find("</script>", from);
  const std::string base64 = html.substr(from, to - from);
  std::string packed;
  int bits = 0;
  unsigned value = 0;
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (const char c : base64) {
    const size_t digit = alphabet.find(c);
    if (digit == std::string::npos) continue;  // '=' and line breaks
    value = (value << 6) | static_cast<unsigned>(digit);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      packed += static_cast<char>((value >> bits) & 0xff);
    }
  }
  z_stream stream{};
  inflateInit(&stream);
  stream.next_in = reinterpret_cast<Bytef*>(packed.data());
  stream.avail_in = static_cast<uInt>(packed.size());
  std::string text;
  char chunk[65536];
  int status = Z_OK;
  while (status == Z_OK) {
    stream.next_out = reinterpret_cast<Bytef*>(chunk);
    stream.avail_out = sizeof chunk;
    status = inflate(&stream, Z_NO_FLUSH);
    text.append(chunk, sizeof chunk - stream.avail_out);
  }
  inflateEnd(&stream);
  return text;
}

// The run sandbox's gaps of issue 39, closed: the keyring and io_uring refused and flagged, shared
// memory past the limit refused, the teacher's environment and the run's world out of the
// algorithm's reach and of the student's page. Each tried again without the sandbox, where it works: the test can fail.
void expectTheRunSandboxHasNoGaps(const fs::path& dir, const std::map<std::string, std::map<std::string, std::string>>& rows,
                                  const std::string& quiet_median, const std::string& language, bool have_key) {
  auto line = [&](const std::string& student) { return rows.at(student).at("line"); };
  auto result = [&](const std::string& student) {
    return readFile((dir / "out" / "runs" / student / "vacuum-seed1.json").string());
  };
  // Refused and flagged, the mark left as earned.
  for (const auto& [student, call] : std::map<std::string, std::string>{{"keyring", "keyctl"}, {"io_uring", "io_uring_setup"}}) {
    expectRefused(dir / "out", student, {student == "keyring" ? "read the session keyring" : "set up an io_uring"});
    EXPECT_EQ(rows.at(student).at("runs_tampered"), "1") << line(student);
    EXPECT_NE(result(student).find("\"" + call + "\""), std::string::npos) << result(student);
    EXPECT_EQ(rows.at(student).at("median"), quiet_median) << line(student);
  }
  // Shared memory counts: a 3 GB shared mapping is refused as a 3 GB heap is, and /dev/shm holds
  // no more than the sandbox's own small tmpfs.
  expectRefused(dir / "out", "shared-memory", {"map 3 GB of shared memory", "write 256 MB in /dev/shm"});
  EXPECT_EQ(rows.at("shared-memory").at("runs_failed"), "0") << line("shared-memory");
  EXPECT_EQ(rows.at("shared-memory").at("median"), quiet_median) << line("shared-memory");
  // Processes of its own, each under the limit, over it together: the run ends with the reason.
  EXPECT_NE(line("fork-memory").find("the algorithm used more than 2048 MB of memory (its processes together)"),
            std::string::npos) << line("fork-memory");
  // The world and the environment in an exception. In its own process (the default) the algorithm
  // finds the run's world by its path (the component's command line) and cannot read it: the
  // exception has the path and nothing of the world. Inside the component (graded again with
  // Component.OwnProcess=off) it reads it: the teacher's row has the exception (no teacher variable
  // in it: the component's environment is the sandbox's), the student's page neither the world's
  // text nor the teacher's folders.
  const std::string world = readFile(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world");
  const std::string thrown = line("world-in-exception");
  EXPECT_NE(thrown.find("the world"), std::string::npos) << thrown;
  // Landlock (Linux 5.13 and later, when enabled) narrows that process's view; without it, the
  // page's withholding below is what stands.
  const bool narrowed = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, 1U /* LANDLOCK_CREATE_RULESET_VERSION */) >= 1;
  if (narrowed) {
    EXPECT_EQ(result("world-in-exception").find("sdf version"), std::string::npos) << result("world-in-exception");
  }
  EXPECT_EQ(result("world-in-exception").find(kTeacherToken), std::string::npos) << result("world-in-exception");
  const fs::path inside = dir / "inside";
  ASSERT_EQ(grade({(dir / "class" / "world-in-exception").string()}, inside, (dir / "inside.log").string(),
                  {"--Component.OwnProcess=off"}),
            0)
      << readFile((dir / "inside.log").string());
  const std::string inside_result = readFile((inside / "runs" / "world-in-exception" / "vacuum-seed1.json").string());
  EXPECT_NE(inside_result.find("sdf version"), std::string::npos) << inside_result.substr(0, 4000);
  EXPECT_EQ(inside_result.find(kTeacherToken), std::string::npos) << inside_result.substr(0, 4000);
  for (const fs::path& out : {dir / "out", inside}) {
    const std::string page = readFile((out / "runs" / "world-in-exception" / "vacuum-seed1.html").string());
    const std::string data = unpackedRunData(page);
    ASSERT_FALSE(data.empty()) << "no run data in the student's page";
    for (const std::string& shown : {page, data}) {
      EXPECT_EQ(shown.find(world.substr(world.size() / 2, 40)), std::string::npos) << "the world is in the student's page";
      EXPECT_EQ(shown.find("<sdf version"), std::string::npos) << "the world is in the student's page";
      EXPECT_EQ(shown.find(dir.string()), std::string::npos) << "the teacher's folders are in the student's page";
      EXPECT_EQ(shown.find(kTeacherToken), std::string::npos);
    }
    if (out == inside) {
      EXPECT_NE(data.find("withheld from the student's page"), std::string::npos) << data.substr(0, 4000);
      // The referee's picture writes the failure in full: not on that page.
      EXPECT_EQ(page.find("The referee's picture at the end"), std::string::npos);
    }
  }

  // Without the sandbox each gets through.
  if (have_key) {
    const std::string keyring = runWithoutSandbox(dir, "keyring", language);
    EXPECT_NE(keyring.find(std::string("exam: the key holds ") + kTeacherKey), std::string::npos) << keyring;
  }
  const std::string uring = runWithoutSandbox(dir, "io_uring", language);
  EXPECT_NE(uring.find("exam: set up an io_uring: done"), std::string::npos) << uring;
  const std::string shared = runWithoutSandbox(dir, "shared-memory", language);
  EXPECT_NE(shared.find("exam: map 3 GB of shared memory: done"), std::string::npos) << shared;
  EXPECT_NE(shared.find("exam: write 256 MB in /dev/shm: done"), std::string::npos) << shared;
  ::unlink("/dev/shm/aula-exam");
  const std::string forked = runWithoutSandbox(dir, "fork-memory", language);
  EXPECT_NE(forked.find("exam: three children of 800 MB each: done"), std::string::npos) << forked;
  EXPECT_EQ(forked.find("MB of memory"), std::string::npos) << forked;
  const std::string open_world = runWithoutSandbox(dir, "world-in-exception", language);
  EXPECT_NE(open_world.find(kTeacherToken), std::string::npos) << open_world.substr(0, 4000);
  EXPECT_NE(open_world.find("<sdf version"), std::string::npos) << open_world.substr(0, 4000);
}

// An exam in `language` (GetParam()): a quiet student and an attacker per attack, in one class.
class ExamIn : public ::testing::TestWithParam<std::string> {};

TEST_P(ExamIn, EachRunSeesOnlyItselfAndNothingLeavesIt) {
  const std::string language = GetParam();
  const fs::path dir = aula::testing::privateDir();
  const std::vector<std::string> attacks = attacksIn(language);
  fs::create_directories(dir / "teacher");
  fs::copy_file(std::string(AULA_SOURCE_DIR) + "/worlds/vacuum.world", dir / "teacher" / "held_out.world");
  const std::string classmate = (dir / "class" / "quiet" / (language == "python" ? "MyAlgorithm.py" : "MyAlgorithm.cpp")).string();
  const std::vector<std::string> targets = {classmate, (dir / "out" / "manifest.json").string(),
                                            (dir / "teacher" / "held_out.world").string(), "/home"};
  std::string joined;
  for (const std::string& target : targets) joined += (joined.empty() ? "" : ":") + target;
  Listener listener;
  const Targets told{joined, (dir / "out" / "grades.csv").string(), listener.port()};
  writeSubmission(dir / "class" / "quiet", "none", language);
  for (const std::string& attack : attacks) writeSubmission(dir / "class" / attack, attack, language, told);
  // The control runs below (no sandbox) are told the same through their environment.
  ::setenv("AULA_EXAM_READ", told.read.c_str(), 1);
  ::setenv("AULA_EXAM_WRITE", told.write.c_str(), 1);
  ::setenv("AULA_EXAM_PORT", std::to_string(told.port).c_str(), 1);
  // What a teacher's session holds: a variable of the environment and a key of the session keyring.
  ::setenv("AULA_EXAM_TEACHER_TOKEN", kTeacherToken, 1);
  const bool have_key = addSessionKey();

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
  // A datagram out of the run: the algorithm's own process may open no socket, and its try flagged
  // its run; the quiet student is not flagged.
  EXPECT_EQ(rows.at("udp").at("runs_tampered"), "1") << rows.at("udp").at("line");
  const std::string udp_result = readFile((dir / "out" / "runs" / "udp" / "vacuum-seed1.json").string());
  EXPECT_NE(udp_result.find("\"socket\""), std::string::npos) << udp_result;
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

  // Without the sandbox, and inside the component, the same reads and datagrams get through: the
  // test can fail.
  for (const std::string attack : {"read", "udp", "find-reference"}) {
    if (attack == "find-reference" && language == "python") continue;
    runWithoutSandbox(dir, attack, language);
  }
  const std::string open_log = readFile((dir / "open-read.log").string());
  EXPECT_NE(open_log.find("exam: read " + (dir / "teacher" / "held_out.world").string() + ": done"), std::string::npos)
      << open_log;
  EXPECT_GT(listener.received(), 0) << "without the sandbox the datagrams should have arrived";
  if (language == "cpp") {
    const std::string found = readFile((dir / "open-find-reference.log").string());
    EXPECT_NE(found.find("exam: load the reference's plugin: done"), std::string::npos) << found;
  }
  expectTheRunSandboxHasNoGaps(dir, rows, alone.at("quiet").at("median"), language, have_key);
  ::unsetenv("AULA_EXAM_READ");
  ::unsetenv("AULA_EXAM_WRITE");
  ::unsetenv("AULA_EXAM_PORT");
  ::unsetenv("AULA_EXAM_TEACHER_TOKEN");
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Exam, ExamIn, ::testing::Values("cpp", "python"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// The build is part of the exam (issue 39): a class of a quiet student and an attacker per attack
// on the build, graded at once. A file name that would have run CMake code is refused in its
// row; a classmate's file (included, or looked for with __has_include), the machine's identity and
// the reference's plugin (.incbin) are out of the build's sight. Graded again with the build out
// of its box (--build-sandbox=off), the same includes and .incbin work: the test can fail.
TEST(Exam, TheBuildIsBoxed) {
  const fs::path dir = aula::testing::privateDir();
  const fs::path class_dir = dir / "class";
  writeSubmission(class_dir / "quiet", "none", "cpp");
  const std::string quiet_source = readFile((class_dir / "quiet" / "MyAlgorithm.cpp").string());
  const std::string classmate = (class_dir / "quiet" / "MyAlgorithm.cpp").string();
  const std::string reference = std::string(AULA_BIN_DIR) + "/../lib/aula/references/libaula_vacuum_reference.so";
  ASSERT_TRUE(fs::exists(reference)) << reference;
  // Each attacker: the quiet student's algorithm, with its attack before it.
  const std::map<std::string, std::string> attacks = {
      {"include-relative", "#include \"../quiet/MyAlgorithm.cpp\"\n"},
      {"include-absolute", "#include \"" + classmate + "\"\n"},
      {"has-include", "#if __has_include(\"" + classmate + "\")\n#error \"exam: a classmate's file is visible\"\n#endif\n" +
                          quiet_source},
      {"incbin-machine-id", "__asm__(\".pushsection .rodata\\n.incbin \\\"/etc/machine-id\\\"\\n.popsection\");\n" + quiet_source},
      {"incbin-reference", "__asm__(\".pushsection .rodata\\n.incbin \\\"" + reference + "\\\"\\n.popsection\");\n" + quiet_source}};
  for (const auto& [student, source] : attacks) {
    fs::create_directories(class_dir / student);
    fs::copy_file(class_dir / "quiet" / "exam_attack.hpp", class_dir / student / "exam_attack.hpp");
    std::ofstream(class_dir / student / "MyAlgorithm.cpp") << source;
  }
  // A file name that, pasted into a build file, ends the string and runs the CMake script the
  // student shipped beside it (found without a '/' in the name: ASCII 47).
  const fs::path pwned = dir / "pwned";
  writeSubmission(class_dir / "inject", "none", "cpp");
  std::ofstream(class_dir / "inject" / "payload.cmake") << "file(WRITE \"" << pwned.string() << "\" \"ran\")\n";
  const std::string injecting =
      "MyAlgorithm.cpp\")\nstring(ASCII 47 S)\nfile(GLOB L \"..${S}..${S}..${S}class${S}inject${S}payload.cmake\")\n"
      "include(${L})\n#.cpp";
  std::ofstream(class_dir / "inject" / injecting) << "// nothing\n";
  // A source that is a link to a classmate's.
  fs::create_directories(class_dir / "link");
  fs::create_symlink(classmate, class_dir / "link" / "MyAlgorithm.cpp");

  ASSERT_EQ(grade({(class_dir / "quiet").string()}, dir / "alone", (dir / "alone.log").string()), 0)
      << readFile((dir / "alone.log").string());
  const auto alone = gradesOf((dir / "alone" / "grades.csv").string());
  std::vector<std::string> folders = {(class_dir / "quiet").string(), (class_dir / "inject").string(),
                                      (class_dir / "link").string()};
  for (const auto& attack : attacks) folders.push_back((class_dir / attack.first).string());
  // From the out folder's build/inject, the payload is at ../../../class/inject: the same depth.
  ASSERT_EQ(grade(folders, dir / "out", (dir / "class.log").string(), {"--similarity=off"}), 0)
      << readFile((dir / "class.log").string());
  const auto rows = gradesOf((dir / "out" / "grades.csv").string());
  auto line = [&](const std::string& student) { return rows.at(student).at("line"); };
  EXPECT_EQ(line("quiet"), alone.at("quiet").at("line"));

  EXPECT_FALSE(fs::exists(pwned)) << "the file name ran CMake code";
  EXPECT_NE(line("inject").find("refused: MyAlgorithm.cpp\\x22)\\x0astring(ASCII 47 S)"), std::string::npos) << line("inject");
  EXPECT_NE(line("inject").find("is not a plain source name"), std::string::npos) << line("inject");
  EXPECT_NE(line("link").find("refused: MyAlgorithm.cpp is a symbolic link"), std::string::npos) << line("link");
  for (const char* student : {"include-relative", "include-absolute", "incbin-machine-id", "incbin-reference"}) {
    EXPECT_NE(line(student).find("did not compile"), std::string::npos) << line(student);
    EXPECT_LT(std::stod(rows.at(student).at("median")), 0.01) << line(student);
  }
  EXPECT_EQ(rows.at("has-include").at("median"), alone.at("quiet").at("median")) << line("has-include");
  EXPECT_EQ(rows.at("has-include").at("runs_failed"), "0") << line("has-include");
  // Nothing of a student's name is in the build file.
  EXPECT_EQ(readFile((dir / "out" / "build" / "inject" / "CMakeLists.txt").string()).find("MyAlgorithm"), std::string::npos);

  // The same file name pasted into a build file, as aula grade once wrote it: it runs.
  const fs::path pasted_project = dir / "out" / "build" / "pasted";  // ../../../class/inject from there too
  fs::create_directories(pasted_project);
  std::ofstream(pasted_project / "CMakeLists.txt") << "cmake_minimum_required(VERSION 3.16)\nproject(pasted NONE)\n"
                                                   << "set(sources\n  \"" << injecting << "\")\n";
  aula::process::ChildProcess pasted({"cmake", "-S", pasted_project.string(), "-B", (dir / "pasted-build").string()},
                                     (dir / "pasted.log").string(), (dir / "pasted.log").string());
  pasted.wait(60s);
  EXPECT_TRUE(fs::exists(pwned)) << "the control did not run the payload: " << readFile((dir / "pasted.log").string());
  // Out of its box, the build reads the class and the machine.
  std::vector<std::string> open_folders;
  for (const char* student : {"include-absolute", "has-include", "incbin-machine-id", "incbin-reference"}) {
    open_folders.push_back((class_dir / student).string());
  }
  ASSERT_EQ(grade(open_folders, dir / "open", (dir / "open.log").string(), {"--similarity=off", "--build-sandbox=off"}), 0)
      << readFile((dir / "open.log").string());
  const auto open = gradesOf((dir / "open" / "grades.csv").string());
  EXPECT_NE(open.at("has-include").at("line").find("a classmate's file is visible"), std::string::npos)
      << open.at("has-include").at("line");
  for (const char* student : {"include-absolute", "incbin-machine-id", "incbin-reference"}) {
    EXPECT_EQ(open.at(student).at("median"), alone.at("quiet").at("median")) << open.at(student).at("line");
  }
  fs::remove_all(dir);
}

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
  argv.insert(argv.end(), {"--seeds=1", "--jobs=1", "--record", "--similarity=off", "--Vacuum.Referee.Duration=120",
                           "--calibration-seeds=off"});
  auto gradeInto = [&](const std::vector<std::string>& before, const fs::path& out, const std::string& log,
                       const std::vector<std::string>& options = {}) {
    std::vector<std::string> command = before;
    command.insert(command.end(), argv.begin(), argv.end());
    command.insert(command.end(), options.begin(), options.end());
    command.push_back("--out=" + out.string());
    aula::process::ChildProcess child(command, log, log);
    return child.wait(300s).value_or(-1);
  };
  // Its builds kept: the room the full grade needs holds them while it runs.
  ASSERT_EQ(gradeInto({}, dir / "roomy", (dir / "roomy.log").string(), {"--keep-builds"}), 0) << readFile((dir / "roomy.log").string());
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

// The reference a student embeds in their own plugin (its bytes built in, written out and loaded
// at run time: what a student can do with any Aula install's file, as an array or by .incbin,
// whatever any box hides) is flagged as the reference: it drives the reference's path (issue 39).
// Its build out of the box, so that the embedding compiles; a quiet student beside it is not flagged.
TEST(Exam, AnEmbeddedReferenceIsFlaggedAsTheReference) {
  const fs::path dir = aula::testing::privateDir();
  const fs::path class_dir = dir / "class";
  writeSubmission(class_dir / "quiet", "none", "cpp");
  const std::string reference = std::string(AULA_BIN_DIR) + "/../lib/aula/references/libaula_vacuum_classic.so";
  ASSERT_TRUE(fs::exists(reference)) << reference;
  fs::create_directories(class_dir / "embedder");
  std::ofstream(class_dir / "embedder" / "MyAlgorithm.cpp")
      << "#include <aula/vacuum/vacuum_algorithm.hpp>\n#include <dlfcn.h>\n#include <cstdlib>\n#include <fstream>\n"
      << "extern \"C\" const char exam_ref_begin[], exam_ref_end[];\n"
      << "__asm__(\".pushsection .rodata\\n.global exam_ref_begin\\nexam_ref_begin:\\n.incbin \\\"" << reference
      << "\\\"\\n.global exam_ref_end\\nexam_ref_end:\\n.popsection\");\n"
      << "namespace aula::vacuum {\nnamespace {\nclass Embedded : public VacuumAlgorithm {\n public:\n"
      << "  explicit Embedded(uint64_t seed) : seed_(seed) {}\n  void execute(VacuumApi& api) override {\n"
      << "    if (!inner_) {\n      const char* tmp = std::getenv(\"TMPDIR\");\n"
      << "      const std::string path = std::string(tmp ? tmp : \"/tmp\") + \"/embedded.so\";\n"
      << "      std::ofstream(path, std::ios::binary).write(exam_ref_begin, exam_ref_end - exam_ref_begin);\n"
      << "      void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);\n"
      << "      using Factory = VacuumAlgorithm* (*)(uint64_t);\n"
      << "      auto factory = library ? reinterpret_cast<Factory>(dlsym(library, \"aula_vacuum_algorithm_v1\")) : nullptr;\n"
      << "      if (!factory) throw std::runtime_error(std::string(\"exam: no embedded reference: \") + dlerror());\n"
      << "      inner_.reset(factory(seed_));\n    }\n    inner_->execute(api);\n  }\n private:\n"
      << "  uint64_t seed_;\n  std::unique_ptr<VacuumAlgorithm> inner_;\n};\n}  // namespace\n"
      << "std::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return std::make_unique<Embedded>(seed); }\n"
      << "}  // namespace aula::vacuum\n";
  ASSERT_EQ(grade({(class_dir / "quiet").string(), (class_dir / "embedder").string()}, dir / "out", (dir / "out.log").string(),
                  {"--similarity=on", "--build-sandbox=off"}),
            0)
      << readFile((dir / "out.log").string());
  const auto rows = gradesOf((dir / "out" / "grades.csv").string());
  EXPECT_EQ(rows.at("embedder").at("runs_failed"), "0") << rows.at("embedder").at("line");
  const std::string csv = readFile((dir / "out" / "similarity.csv").string());
  EXPECT_NE(csv.find("embedder,reference 'classic',yes,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("quiet,reference 'classic',yes,"), std::string::npos) << csv;
  EXPECT_NE(readFile((dir / "out" / "report.html").string()).find("embedder matches reference &#39;classic&#39;"), std::string::npos);
  fs::remove_all(dir);
}
