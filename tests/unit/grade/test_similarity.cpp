// Similarity on plain data: tokens that see through names and comments, winnowed fingerprints
// that survive reordering, scores and line ranges, and paths compared on sim time.
#include <aula/grade/similarity.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

namespace {
using namespace aula::grade;

const char* kOriginal = R"(// a student's helper
double clamp(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }
class Cleaner {
 public:
  void step(double range_m) {
    if (range_m < 0.4) { turning_ = true; count_ += 1; }
    speed_ = clamp(range_m * 0.8, 0.0, 0.5);
    for (int i = 0; i < 10; ++i) total_ += i * speed_;
  }
 private:
  bool turning_ = false;
  int count_ = 0;
  double speed_ = 0, total_ = 0;
};
)";

// The same code, every name changed, comments changed, the class's parts reordered.
const char* kDisguised = R"(
class Roomba {
 private:
  bool spinning = false;   /* renamed */
  int bumps = 0;
  double v = 0, sum = 0;
 public:
  void step(double d) {
    if (d < 0.4) { spinning = true; bumps += 1; }
    v = limit(d * 0.8, 0.0, 0.5);
    for (int k = 0; k < 10; ++k) sum += k * v;
  }
};
double limit(double x, double a, double b) { return x < a ? a : x > b ? b : x; }
)";

const char* kOther = R"(
#include <vector>
struct Grid { std::vector<int> cells; int width = 0; };
int count(const Grid& g) {
  int n = 0;
  for (int c : g.cells) n += c == 1 ? 1 : 0;
  while (n > 100) n /= 2;
  return n * g.width;
}
)";

TEST(Similarity, TokensSeeThroughNamesCommentsAndLayout) {
  const auto a = tokenize("int speed_m = 3; // fast\n", false);
  const auto b = tokenize("int   v =\n 7; /* slow */", false);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].text, b[i].text);
  EXPECT_EQ(a[1].text, "I");
  EXPECT_EQ(a[3].text, "N");
  const auto py = tokenize("def f(x):  # comment\n    return 'a' + x\n", true);
  EXPECT_EQ(py.front().text, "def");
  EXPECT_EQ(py.back().line, 2);
}

TEST(Similarity, ARenamedAndReorderedCopyScoresHighAnOtherProgramLow) {
  const auto original = fingerprints(tokenize(kOriginal, false), 8, 4);
  const auto disguised = fingerprints(tokenize(kDisguised, false), 8, 4);
  const auto other = fingerprints(tokenize(kOther, false), 8, 4);
  const CodeMatch copy = compareCode(original, disguised, {});
  EXPECT_GE(copy.score, 0.6);
  ASSERT_FALSE(copy.ranges.empty());
  EXPECT_GE(copy.ranges.front().a_first, 1);
  EXPECT_LT(compareCode(original, other, {}).score, 0.2);
  // What the template gives everyone is no likeness.
  EXPECT_DOUBLE_EQ(compareCode(original, original, original).score, 0.0);
}

// kOriginal with statements that change nothing sprinkled between its own, and one constant changed.
const char* kWithNoOps = R"(// a student's helper
double clamp(double v, double lo, double hi) { ; int spare = 2; (void)hi; return v < lo ? lo : v > hi ? hi : v; }
class Cleaner {
 public:
  void step(double range_m) {
    int unused = 7;
    if (range_m < 0.4) { turning_ = true; (void)range_m; count_ += 1; ; }
    speed_ = speed_;
    speed_ = clamp(range_m * 0.9, 0.0, 0.5);
    total_ *= 1;
    if (false) { speed_ = 99; }
    total_ += 0;
    count_;
    {}
    for (int i = 0; i < 10; ++i) total_ += i * speed_;
    ;
  }
 private:
  bool turning_ = false;
  int count_ = 0;
  double speed_ = 0, total_ = 0;
};
)";

const char* kPythonOriginal = R"(def step(state, range_m):
    if range_m < 0.4:
        state.turning = True
        state.count += 1
    state.speed = min(max(range_m * 0.8, 0.0), 0.5)
    for i in range(10):
        state.total += i * state.speed
    return state.speed
)";

const char* kPythonWithNoOps = R"(def step(state, range_m):
    """steps"""
    if range_m < 0.4:
        pass
        state.turning = True
        unused = 3
        state.count += 1
    range_m = range_m
    state.speed = min(max(range_m * 0.9, 0.0), 0.5)
    None
    for i in range(10):
        state.total += i * state.speed
        i += 0
    return state.speed
)";

// A disguise that sprinkles statements that change nothing (and changes a constant) breaks most
// k-grams of the tokens as written; without those statements the copy is the original again.
TEST(Similarity, StatementsThatChangeNothingDoNotHideACopy) {
  for (const bool python : {false, true}) {
    SCOPED_TRACE(python ? "Python" : "C++");
    const std::string original = python ? kPythonOriginal : kOriginal, copy = python ? kPythonWithNoOps : kWithNoOps;
    const double as_written = compareCode(fingerprints(tokenize(original, python), 8, 4), fingerprints(tokenize(copy, python), 8, 4), {}).score;
    const double normalised = compareCode(fingerprints(withoutNoOps(tokenize(original, python), python), 8, 4),
                                          fingerprints(withoutNoOps(tokenize(copy, python), python), 8, 4), {}).score;
    EXPECT_LE(as_written, normalised - 0.35) << "the disguise works on the tokens as written";
    EXPECT_GE(normalised, 0.9) << "as written: " << as_written;
  }
  // What the rules drop, and what they keep: a used declaration, a live branch, a real update.
  const auto kept = withoutNoOps(tokenize("int n = 0; if (x) { n += 1; } total += 0.5; f(n);", false), false);
  EXPECT_EQ(kept.size(), tokenize("int n = 0; if (x) { n += 1; } total += 0.5; f(n);", false).size());
  EXPECT_LT(compareCode(codeFingerprints(kOriginal, false), codeFingerprints(kOther, false), {}).score, 0.2);
}

TEST(Similarity, WinnowingKeepsAFingerprintOfEveryLongSharedRun) {
  // Any run of at least window + k - 1 tokens in both gives a shared fingerprint (the guarantee).
  std::string shared;
  for (int i = 0; i < 6; ++i) shared += "x = y + " + std::to_string(i) + " * z; ";
  const auto a = fingerprints(tokenize("int a; if (b) c(); " + shared, false), 5, 4);
  const auto b = fingerprints(tokenize(shared + " while (q) { r--; }", false), 5, 4);
  EXPECT_GT(compareCode(a, b, {}).score, 0.0);
}

// The rules (aula grade's --similarity-code and --similarity-shared) decide the flag: the same pair
// of identical files, flagged or not.
TEST(Similarity, TheRulesDecideTheFlag) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("aula-similarity-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string program = std::string(kOriginal) + kOther + kDisguised;
  for (const char* student : {"ana", "ben"}) std::ofstream(dir / (std::string(student) + ".cpp")) << program;
  const std::vector<Submitted> students = {{"ana", {(dir / "ana.cpp").string()}}, {"ben", {(dir / "ben.cpp").string()}}};
  const size_t shared = compareCode(codeFingerprints(program, false), codeFingerprints(program, false), {}).shared;
  ASSERT_GE(shared, SimilarityRules{}.code_min_shared);
  EXPECT_TRUE(compareClass(students, {}, {}).at(0).flagged);
  SimilarityRules rules;
  rules.code_threshold = 1.0;  // "or more": a score of 1 still flags
  EXPECT_TRUE(compareClass(students, {}, {}, rules).at(0).flagged);
  rules.code_min_shared = shared + 1;
  EXPECT_FALSE(compareClass(students, {}, {}, rules).at(0).flagged);
  std::filesystem::remove_all(dir);
}

TEST(Similarity, PathsAreComparedAtTheSameSimTimes) {
  nlohmann::json trace = {{"samples", {{"period_s", 0.1}, {"x_mm", {1000, 100, 100}}, {"y_mm", {0, 0, 0}}}}};
  const Path a = pathOfTrace(trace);
  ASSERT_EQ(a.x_m.size(), 3u);
  EXPECT_DOUBLE_EQ(a.x_m[2], 1.2);  // delta-encoded millimetres
  EXPECT_NEAR(pathLength(a), 0.2, 1e-12);
  Path b = a;
  b.y_m = {0.3, 0.3, 0.3};
  EXPECT_NEAR(meanDistance(a, b), 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(meanDistance(a, a), 0.0);
  b.period_s = 0.2;
  EXPECT_TRUE(std::isnan(meanDistance(a, b)));
}

}  // namespace

namespace {
std::string readData(const std::string& path) {
  std::ifstream in(std::string(AULA_SOURCE_DIR) + "/tests/data/" + path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
}  // namespace

// Across the two languages (issue 39): a line-by-line Python port of a C++ program
// (tests/data: the vacuum bounce and its port, which earn the same report) shares almost nothing
// as written, and most of its fingerprints in the common form; two unrelated programs of the two
// languages share little in either.
TEST(Similarity, APythonPortOfACppProgramIsSeenInTheCommonForm) {
  const std::string cpp = readData("plugins/vacuum_bounce.cpp"), py = readData("python/vacuum_bounce/MyAlgorithm.py");
  const double as_written = compareCode(codeFingerprints(cpp, false), codeFingerprints(py, true), {}).score;
  const CodeMatch common = compareCode(codeFingerprints(cpp, false, CodeForm::Common), codeFingerprints(py, true, CodeForm::Common), {});
  std::cout << "as written " << as_written << ", common form " << common.score << " (" << common.shared << " shared)\n";
  EXPECT_LT(as_written, 0.1);
  EXPECT_GE(common.score, 0.6);
  const std::string other = readData("python/teletaxi_follow/MyAlgorithm.py");
  EXPECT_LT(compareCode(codeFingerprints(cpp, false, CodeForm::Common), codeFingerprints(other, true, CodeForm::Common), {}).score, 0.2);
}
