// Code similarity: tokens, winnowed k-gram fingerprints, a pair's score and its matching lines.
// What is dropped before fingerprinting (dead statements, no-ops) is similarity_dead_code.cpp.
#include "aula/grade/similarity.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace aula::grade {
namespace {

const std::set<std::string>& keywords(bool python) {
  static const std::set<std::string> cpp = {
      "if", "else", "for", "while", "do", "switch", "case", "default", "break", "continue", "return", "class", "struct",
      "public", "private", "protected", "const", "static", "auto", "void", "bool", "int", "double", "float", "char",
      "long", "unsigned", "new", "delete", "true", "false", "nullptr", "this", "virtual", "override", "template",
      "typename", "namespace", "using", "std", "try", "catch", "throw", "sizeof", "enum", "operator"};
  static const std::set<std::string> py = {
      "if", "elif", "else", "for", "while", "break", "continue", "return", "class", "def", "self", "True", "False",
      "None", "and", "or", "not", "in", "is", "import", "from", "as", "try", "except", "finally", "raise", "with",
      "lambda", "pass", "global", "nonlocal", "yield", "del", "assert"};
  return python ? py : cpp;
}

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Skips a comment or a string at `i`; true when it did (a string becomes one "S" token).
bool skipCommentOrString(const std::string& s, size_t& i, int& line, bool python, std::vector<Token>& out) {
  const char c = s[i];
  if ((python && c == '#') || (!python && s.compare(i, 2, "//") == 0)) {
    while (i < s.size() && s[i] != '\n') ++i;
    return true;
  }
  if (!python && s.compare(i, 2, "/*") == 0) {
    const size_t end = s.find("*/", i + 2);
    const size_t stop = end == std::string::npos ? s.size() : end + 2;
    line += static_cast<int>(std::count(s.begin() + static_cast<long>(i), s.begin() + static_cast<long>(stop), '\n'));
    i = stop;
    return true;
  }
  if (c != '"' && c != '\'') return false;
  const bool triple = python && s.compare(i, 3, std::string(3, c)) == 0;
  const std::string close = triple ? std::string(3, c) : std::string(1, c);
  const int start_line = line;
  size_t j = i + close.size();
  while (j < s.size() && s.compare(j, close.size(), close) != 0) {
    if (s[j] == '\\') ++j;
    else if (s[j] == '\n') ++line;
    ++j;
  }
  out.push_back({"S", start_line, ""});
  i = std::min(s.size(), j + close.size());
  return true;
}

}  // namespace

std::vector<Token> tokenize(const std::string& source, bool python) {
  std::vector<Token> tokens;
  int line = 1;
  size_t i = 0;
  while (i < source.size()) {
    const char c = source[i];
    if (c == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(c)) != 0 || (!python && c == '#')) {  // a C++ #include line is layout
      if (c == '#') {
        while (i < source.size() && source[i] != '\n') ++i;
      } else {
        ++i;
      }
      continue;
    }
    if (skipCommentOrString(source, i, line, python, tokens)) continue;
    if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      const size_t start = i;
      while (i < source.size() && (identifierChar(source[i]) || source[i] == '.')) ++i;
      tokens.push_back({"N", line, source.substr(start, i - start)});
    } else if (identifierChar(c)) {
      const size_t start = i;
      while (i < source.size() && identifierChar(source[i])) ++i;
      const std::string word = source.substr(start, i - start);
      const bool keyword = keywords(python).count(word) != 0;
      tokens.push_back({keyword ? word : "I", line, keyword ? "" : word});
    } else {
      tokens.push_back({std::string(1, c), line, ""});
      ++i;
    }
  }
  return tokens;
}

std::vector<Fingerprint> codeFingerprints(const std::vector<SourceText>& files, CodeForm form) {
  std::vector<std::vector<Token>> tokens;
  std::vector<bool> python;
  for (const SourceText& file : files) {
    tokens.push_back(tokenize(file.text, file.python));
    python.push_back(file.python);
  }
  const std::vector<std::string> unread = unreadNames(tokens, python);
  // The functions left empty once their dead statements are dropped (`void nop() { int k = 0; }`
  // is as empty as `{}`): their calls are dropped with the dead statements, in one pass.
  std::vector<std::vector<Token>> cleaned;
  std::vector<std::vector<Token>> live_statements;
  for (size_t f = 0; f < files.size(); ++f) {
    live_statements.push_back(withoutDeadStatements(tokens[f], python[f], unread));
    cleaned.push_back(withoutNoOps(live_statements.back(), python[f]));
  }
  const std::vector<std::string> empty = emptyFunctions(live_statements, python);
  std::vector<Fingerprint> prints;
  for (size_t f = 0; f < files.size(); ++f) {
    const std::vector<Token> live = empty.empty() ? cleaned[f] : withoutNoOps(withoutDeadStatements(tokens[f], python[f], unread, empty), python[f]);
    for (Fingerprint print : fingerprints(form == CodeForm::Common ? commonForm(live, python[f]) : live)) {
      print.file = static_cast<int>(f);
      prints.push_back(print);
    }
  }
  return prints;
}

std::vector<Fingerprint> codeFingerprints(const std::string& source, bool python, CodeForm form) {
  return codeFingerprints(std::vector<SourceText>{{source, python}}, form);
}

std::vector<Fingerprint> fingerprints(const std::vector<Token>& tokens, size_t k, size_t window) {
  std::vector<Fingerprint> grams;
  for (size_t i = 0; i + k <= tokens.size(); ++i) {
    uint64_t hash = 1469598103934665603ull;  // FNV-1a over the k tokens
    for (size_t j = i; j < i + k; ++j) {
      for (const char c : tokens[j].text + " ") hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    grams.push_back({hash, tokens[i].line, tokens[i + k - 1].line});
  }
  std::vector<Fingerprint> chosen;
  size_t last = SIZE_MAX;
  for (size_t start = 0; start + window <= grams.size() || (start == 0 && !grams.empty()); ++start) {
    const size_t end = std::min(grams.size(), start + window);
    size_t best = start;
    for (size_t j = start; j < end; ++j) {
      if (grams[j].hash <= grams[best].hash) best = j;  // the rightmost smallest
    }
    if (best != last) chosen.push_back(grams[best]);
    last = best;
    if (end == grams.size()) break;
  }
  return chosen;
}

CodeMatch compareCode(const std::vector<Fingerprint>& a, const std::vector<Fingerprint>& b,
                      const std::vector<Fingerprint>& starter) {
  std::unordered_set<uint64_t> common;
  for (const Fingerprint& f : starter) common.insert(f.hash);
  std::unordered_map<uint64_t, const Fingerprint*> in_b;
  size_t b_own = 0;
  for (const Fingerprint& f : b) {
    if (common.count(f.hash) != 0) continue;
    b_own += in_b.emplace(f.hash, &f).second ? 1 : 0;
  }
  std::set<uint64_t> a_own, shared;
  CodeMatch match;
  for (const Fingerprint& f : a) {
    if (common.count(f.hash) != 0 || !a_own.insert(f.hash).second) continue;
    const auto it = in_b.find(f.hash);
    if (it == in_b.end()) continue;
    shared.insert(f.hash);
    auto& ranges = match.ranges;
    const Fingerprint& g = *it->second;
    // Runs of matches next to each other in both files become one range.
    if (!ranges.empty() && ranges.back().a_file == f.file && ranges.back().b_file == g.file &&
        f.first_line <= ranges.back().a_last + 1 && g.first_line <= ranges.back().b_last + 1 && g.last_line >= ranges.back().b_first - 1) {
      ranges.back().a_last = std::max(ranges.back().a_last, f.last_line);
      ranges.back().b_first = std::min(ranges.back().b_first, g.first_line);
      ranges.back().b_last = std::max(ranges.back().b_last, g.last_line);
    } else {
      ranges.push_back({f.file, f.first_line, f.last_line, g.file, g.first_line, g.last_line});
    }
  }
  const size_t smaller = std::min(a_own.size(), b_own);
  match.shared = shared.size();
  match.score = smaller == 0 ? 0.0 : static_cast<double>(shared.size()) / static_cast<double>(smaller);
  return match;
}

}  // namespace aula::grade
