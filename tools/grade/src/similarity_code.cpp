// Code similarity: tokens, winnowed k-gram fingerprints, a pair's score and its matching lines.
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

namespace {

bool isZero(const Token& t) { return t.text == "N" && t.raw.find_first_not_of("0.") == std::string::npos; }
bool isOne(const Token& t) { return t.text == "N" && (t.raw == "1" || t.raw == "1.0" || t.raw == "1."); }

// How often each identifier is written in the file.
std::unordered_map<std::string, int> identifierCounts(const std::vector<Token>& tokens) {
  std::unordered_map<std::string, int> counts;
  for (const Token& t : tokens) {
    if (t.text == "I") ++counts[t.raw];
  }
  return counts;
}

// C++: how many tokens from `i` (a statement's start) make a statement that changes nothing; 0: none.
size_t cppNoOp(const std::vector<Token>& t, size_t i, const std::unordered_map<std::string, int>& uses) {
  auto is = [&](size_t k, const char* text) { return k < t.size() && t[k].text == text; };
  auto operand = [&](size_t k) { return k < t.size() && (t[k].text == "I" || t[k].text == "N" || t[k].text == "S"); };
  if (is(i, ";")) return 1;
  if (operand(i) && is(i + 1, ";")) return 2;                                          // x;
  if (is(i, "(") && is(i + 1, "void") && is(i + 2, ")") && operand(i + 3) && is(i + 4, ";")) return 5;  // (void)x;
  if (is(i, "I") && is(i + 1, "=") && is(i + 2, "I") && t[i].raw == t[i + 2].raw && is(i + 3, ";")) return 4;  // x = x;
  if (is(i, "I") && (is(i + 1, "+") || is(i + 1, "-")) && is(i + 2, "=") && i + 3 < t.size() && isZero(t[i + 3]) && is(i + 4, ";")) return 5;
  if (is(i, "I") && (is(i + 1, "*") || is(i + 1, "/")) && is(i + 2, "=") && i + 3 < t.size() && isOne(t[i + 3]) && is(i + 4, ";")) return 5;
  if (is(i, "if") && is(i + 1, "(") && (is(i + 2, "false") || (i + 2 < t.size() && isZero(t[i + 2]))) && is(i + 3, ")")) {
    size_t k = i + 4, depth = 0;  // the dead branch: a block, or one statement
    do {
      if (is(k, "{")) ++depth;
      if (is(k, "}") && depth > 0) --depth;
      ++k;
    } while (k < t.size() && (depth > 0 || (!is(k - 1, "}") && !is(k - 1, ";"))));
    return is(k, "else") ? 0 : k - i;
  }
  // A variable declared and never written again: `int unused = 0;`.
  static const std::set<std::string> types = {"int", "double", "float", "bool", "auto", "char", "long", "unsigned", "const"};
  size_t k = i;
  while (k < t.size() && types.count(t[k].text) != 0) ++k;
  if (k > i && is(k, "I") && uses.at(t[k].raw) == 1 && (is(k + 1, "=") || is(k + 1, ";"))) {
    while (k < t.size() && !is(k, ";") && !is(k, "{") && !is(k, "}")) ++k;
    return is(k, ";") ? k + 1 - i : 0;
  }
  return 0;
}

// Python: how many tokens from `i` (its line's first) make a line that changes nothing; 0: none.
size_t pythonNoOp(const std::vector<Token>& t, size_t i, const std::unordered_map<std::string, int>& uses) {
  size_t end = i;
  while (end < t.size() && t[end].line == t[i].line) ++end;
  const size_t n = end - i;
  auto is = [&](size_t k, const char* text) { return k < end && t[k].text == text; };
  if (is(i, "pass") && n == 1) return 1;
  static const std::set<std::string> lone = {"I", "N", "S", "None", "True", "False"};
  if (n == 1 && lone.count(t[i].text) != 0) return 1;  // a name, a constant or a docstring alone
  if (n == 3 && is(i, "I") && is(i + 1, "=") && is(i + 2, "I") && t[i].raw == t[i + 2].raw) return 3;
  if (n == 4 && is(i, "I") && (is(i + 1, "+") || is(i + 1, "-")) && is(i + 2, "=") && isZero(t[i + 3])) return 4;
  if (n >= 3 && is(i, "I") && is(i + 1, "=") && !is(i + 2, "=") && uses.at(t[i].raw) == 1) return n;  // never used again
  return 0;
}

}  // namespace

std::vector<Token> withoutNoOps(const std::vector<Token>& tokens, bool python) {
  const auto uses = identifierCounts(tokens);
  std::vector<Token> out;
  size_t i = 0;
  while (i < tokens.size()) {
    size_t skip = 0;
    if (python) {
      if (i == 0 || tokens[i - 1].line != tokens[i].line) skip = pythonNoOp(tokens, i, uses);
    } else if (tokens[i].text == "{" && i + 1 < tokens.size() && tokens[i + 1].text == "}") {
      skip = 2;  // an empty block
    } else if (out.empty() || out.back().text == ";" || out.back().text == "{" || out.back().text == "}") {
      skip = cppNoOp(tokens, i, uses);
    }
    if (skip > 0) {
      i += skip;
      continue;
    }
    out.push_back(tokens[i++]);
  }
  return out;
}

std::vector<Fingerprint> codeFingerprints(const std::string& source, bool python, CodeForm form) {
  const std::vector<Token> tokens = withoutNoOps(tokenize(source, python), python);
  return fingerprints(form == CodeForm::Common ? commonForm(tokens, python) : tokens);
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
    const auto a_lines = std::make_pair(f.first_line, f.last_line);
    const auto b_lines = std::make_pair(it->second->first_line, it->second->last_line);
    // Runs of matches next to each other in both files become one range.
    if (!ranges.empty() && a_lines.first <= ranges.back().first.second + 1 && b_lines.first <= ranges.back().second.second + 1 &&
        b_lines.second >= ranges.back().second.first - 1) {
      ranges.back().first.second = std::max(ranges.back().first.second, a_lines.second);
      ranges.back().second.first = std::min(ranges.back().second.first, b_lines.first);
      ranges.back().second.second = std::max(ranges.back().second.second, b_lines.second);
    } else {
      ranges.push_back({a_lines, b_lines});
    }
  }
  const size_t smaller = std::min(a_own.size(), b_own);
  match.shared = shared.size();
  match.score = smaller == 0 ? 0.0 : static_cast<double>(shared.size()) / static_cast<double>(smaller);
  return match;
}

}  // namespace aula::grade
