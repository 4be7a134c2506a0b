#pragma once
// Similarity between students (`aula grade --similarity`): pairs for a teacher to look at, never a
// change of mark.
// - Code: each submission's tokens, of all its files at once (C++ or Python; comments and layout
//   dropped, identifiers, numbers and strings each one class, so renaming changes nothing; the
//   statements that change nothing and the dead ones dropped), fingerprinted by winnowing
//   k-grams of tokens (Schleimer, Wilkerson, Aiken 2003: MOSS's algorithm), less the fingerprints of
//   the exercise's template that everyone starts from. A pair's score is the share of the smaller
//   submission's fingerprints the other has too; reordered functions keep their fingerprints. The
//   evidence: the matching line ranges in both files.
// - Behaviour: for the same world and seed, the mean distance between two students' true poses at
//   the same sim time (the referee's traces, 10 Hz). Differently written code that drives the same
//   path is a signal too: a transliteration from one language to another.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aula::grade {

struct Token {
  std::string text;  // a keyword or operator as written; "I" identifier, "N" number, "S" string
  int line = 0;
  std::string raw;   // an identifier or number as written (what the no-op rules look at)
};

// The tokens of a source file; `python` chooses the language (else C++).
std::vector<Token> tokenize(const std::string& source, bool python);
// The tokens less the statements that change nothing, which a disguise sprinkles in to break
// every k-gram: C++ empty statements and blocks, a lone `x;`, `(void)x;`, `x = x;`, `x += 0;`,
// `x *= 1;`, `if (false) {...}`, a variable declared and never used again; Python `pass`, a lone
// name or constant on its line, `x = x`, `x += 0` and a name assigned and never used again.
std::vector<Token> withoutNoOps(const std::vector<Token>& tokens, bool python);

// Dead code, seen across all of a submission's files (`files`: each file's tokens, `python` each
// file's language): the names whose value nothing reads. A name is read when it appears in a
// statement that stores no name (a call, a condition, a return, a loop's head...) or in one that
// stores a name that is read, other than as an assignment's target; `x = 5; x = x + 1; y = x;`
// with y never read leaves x and y unread, and `if (c) y = 1;` stores y as `y = 1;` does.
// Only plain names and `this->`/`self.` members are stores: `api.motors.v = 1` is a read of all.
std::vector<std::string> unreadNames(const std::vector<std::vector<Token>>& files, const std::vector<bool>& python);
// The functions whose body is empty, across all of a submission's files (`files` less their dead
// statements): C++ `void nop() {}`, Python `def nop(): pass` (or a docstring alone, or nothing
// left) followed by another definition or the end.
std::vector<std::string> emptyFunctions(const std::vector<std::vector<Token>>& files, const std::vector<bool>& python);
// The tokens less the dead statements: a store to a name in `unread` (`junk = 5;`, `junk += i;`,
// `junk++;`, `int junk;`, `if (c) junk = 1;`), an expression statement that calls nothing and stores nothing
// (`a + b;`, `(void)(x * 2);`, Python `x + 1`, `(a, b)`), and a call alone of one of `empty_functions` (`nop();`).
std::vector<Token> withoutDeadStatements(const std::vector<Token>& tokens, bool python, const std::vector<std::string>& unread,
                                         const std::vector<std::string>& empty_functions = {});

struct Fingerprint {
  uint64_t hash = 0;
  int first_line = 0, last_line = 0;  // the lines its k-gram spans
  int file = 0;                       // which of the submission's files (codeFingerprints' order)
};

// Winnowing: of every window of `window` consecutive k-gram hashes, the smallest (rightmost on a tie).
std::vector<Fingerprint> fingerprints(const std::vector<Token>& tokens, size_t k = 12, size_t window = 8);
// The tokens of either language in one form, to compare a C++ file with a Python one (a
// line-by-line translation): what only one language writes is dropped (brackets, `;` and `:`,
// types and declarations' type names, `std::`, `this->` and `self.`, `def`, `math.`, casts), and
// what both write differently is written one way (`&&` and, `||` or, `!` not, `->` ., `elif`
// else if, true True, nullptr None).
std::vector<Token> commonForm(const std::vector<Token>& tokens, bool python);

// How a source is fingerprinted: as written (a pair in one language), or in the common form (a
// pair across the two).
enum class CodeForm { AsWritten, Common };
// A source's fingerprints as similarity compares them: tokenize, withoutDeadStatements,
// withoutNoOps, then the calls of emptyFunctions dropped, (commonForm,) fingerprints.
std::vector<Fingerprint> codeFingerprints(const std::string& source, bool python, CodeForm form = CodeForm::AsWritten);
struct SourceText {
  std::string text;
  bool python = false;
};
// A submission of several files as one: the union of its files' fingerprints (each marked with
// its file's index), its dead names found across all of them, so code moved into a helper file
// still matches and a name written in one file and read in another is read.
std::vector<Fingerprint> codeFingerprints(const std::vector<SourceText>& files, CodeForm form = CodeForm::AsWritten);

// Lines that match in two submissions: a's file a_file, lines a_first-a_last, and b's.
struct MatchedLines {
  int a_file = 0, a_first = 0, a_last = 0;
  int b_file = 0, b_first = 0, b_last = 0;
};
struct CodeMatch {
  double score = 0;  // shared fingerprints over the smaller set, 0-1
  size_t shared = 0;  // how many
  std::vector<MatchedLines> ranges;
};

// `starter`: the template's fingerprints, shared by everyone and so not counted (both forms of
// both languages' templates: a hash of one form never stands for code of the other).
CodeMatch compareCode(const std::vector<Fingerprint>& a, const std::vector<Fingerprint>& b,
                      const std::vector<Fingerprint>& starter);

// A run's true path, from its trace: x, y in metres every period_s of sim time.
struct Path {
  double period_s = 0.1;
  std::vector<double> x_m, y_m;
};
Path pathOfTrace(const nlohmann::json& trace);
// The mean distance between the two paths at the same sim times (the shorter's length), in metres;
// NaN when they have no sample in common or a different period.
double meanDistance(const Path& a, const Path& b);
double pathLength(const Path& path);

struct Submitted {
  std::string student;
  // Every source of the hand-in (.cpp, .hpp, .py...: submissionFiles), compared as one; none for
  // a built-in whose sources are not installed (compared by behaviour only).
  std::vector<std::string> sources;
  // A known algorithm ("reference 'classic'", "known 'NAME'"): compared with every student, never
  // with another known one; a flagged pair reads "STUDENT matches reference 'classic'".
  bool known = false;
};

struct PairSimilarity {
  std::string a, b;
  double code_score = 0;    // across the two languages: in the common form
  bool across_languages = false;
  double behaviour_m = -1;  // the median over the runs compared of the mean distance; -1: none
  int runs_compared = 0;
  bool flagged = false;
  std::string evidence;     // "MyAlgorithm.cpp:10-24 ~ MyAlgorithm.cpp:40-54; ..." and the runs compared
};

// What flags a pair; the defaults are `aula grade`'s (its --similarity-code, --similarity-shared
// and --similarity-path options).
struct SimilarityRules {
  double code_threshold = 0.6;        // flagged at or above this share of fingerprints,
  size_t code_min_shared = 25;        // and at least this many: a short program shares a few by chance
  double behaviour_threshold_m = 0.05;  // flagged at or below this mean distance, for paths that moved
  double moved_m = 1.0;               // paths shorter than this say nothing (a robot that stays still)
};

// Every pair of `students` but two known ones; `results` are the runs' results (their "log" names the trace beside
// them); `starter` the exercise's templates' fingerprints. Pairs sorted, flagged first.
std::vector<PairSimilarity> compareClass(const std::vector<Submitted>& students, const std::vector<nlohmann::json>& results,
                                         const std::vector<Fingerprint>& starter, const SimilarityRules& rules = {});

std::string similarityCsv(const std::vector<PairSimilarity>& pairs);
// The report's section: the rules that flagged, and the flagged pairs, each with its two files side by side.
std::string similarityHtml(const std::vector<PairSimilarity>& pairs, const std::vector<Submitted>& students,
                           const SimilarityRules& rules);

}  // namespace aula::grade
