// Similarity's dead code: statements dropped before fingerprinting (stores nothing reads, values
// computed and dropped, calls of empty functions) and no-ops, so that padding hides no copy.
#include <algorithm>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "aula/grade/similarity.hpp"
#include "similarity_statements.hpp"

namespace aula::grade {

using code_statements::isCloseBracket;
using code_statements::isOpenBracket;
using code_statements::pastAccessLabels;
using code_statements::Statement;
using code_statements::statementsOf;
using code_statements::storedAt;

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

std::vector<std::string> unreadNames(const std::vector<std::vector<Token>>& files, const std::vector<bool>& python) {
  // A worklist, each statement's reads taken once: a chain of any length, a declaration of any
  // number of names, cost one pass (a student's file is untrusted).
  std::vector<std::pair<size_t, Statement>> statements;  // (file, statement)
  std::unordered_map<std::string, std::vector<size_t>> stores;  // name -> the statements that store it
  std::vector<bool> taken;
  std::unordered_set<std::string> read;
  std::vector<std::string> pending;
  auto take = [&](size_t index) {
    if (taken[index]) return;
    taken[index] = true;
    const auto& [file, s] = statements[index];
    const std::unordered_set<std::string> own(s.targets.begin(), s.targets.end());
    for (size_t i = s.begin; i < s.end; ++i) {
      const Token& token = files[file][i];
      if (token.text != "I" || own.count(token.raw) != 0 || storedAt(files[file], i, s, python[file])) continue;
      if (read.insert(token.raw).second) pending.push_back(token.raw);
    }
  };
  for (size_t f = 0; f < files.size(); ++f) {
    for (Statement& s : statementsOf(files[f], python[f])) {
      for (const std::string& name : s.targets) stores[name].push_back(statements.size());
      statements.emplace_back(f, std::move(s));
    }
  }
  taken.assign(statements.size(), false);
  for (size_t i = 0; i < statements.size(); ++i) {
    if (statements[i].second.targets.empty() && !statements[i].second.pure) take(i);  // a dropped value reads nothing
  }
  while (!pending.empty()) {
    const std::string name = pending.back();
    pending.pop_back();
    const auto it = stores.find(name);
    if (it == stores.end()) continue;
    for (const size_t index : it->second) take(index);
  }
  std::vector<std::string> unread;
  for (const auto& [name, where] : stores) {
    if (read.count(name) == 0) unread.push_back(name);
  }
  std::sort(unread.begin(), unread.end());
  return unread;
}

namespace {

// For each bracket, the index of the one that closes it (SIZE_MAX: none): one pass, whatever the nesting.
std::vector<size_t> closingBrackets(const std::vector<Token>& t) {
  std::vector<size_t> closing(t.size(), SIZE_MAX), open;
  for (size_t i = 0; i < t.size(); ++i) {
    if (isOpenBracket(t[i].text)) open.push_back(i);
    if (isCloseBracket(t[i].text) && !open.empty()) {
      closing[open.back()] = i;
      open.pop_back();
    }
  }
  return closing;
}

// Whether `[begin, end)` is a call of one of `names` and nothing else: `[this->|self.] NAME(...)` (C++: and `;`).
bool callOf(const std::vector<Token>& t, size_t begin, size_t end, bool python, const std::vector<size_t>& closing,
            const std::unordered_set<std::string>& names) {
  size_t i = begin;
  if (!python && i + 2 < end && t[i].text == "this" && t[i + 1].text == "-" && t[i + 2].text == ">") i += 3;
  if (python && i + 1 < end && t[i].text == "self" && t[i + 1].text == ".") i += 2;
  if (i + 1 >= end || t[i].text != "I" || t[i + 1].text != "(" || names.count(t[i].raw) == 0) return false;
  return closing[i + 1] + (python ? 1 : 2) == end && (python || t[end - 1].text == ";");
}

}  // namespace

std::vector<std::string> emptyFunctions(const std::vector<std::vector<Token>>& files, const std::vector<bool>& python) {
  static const std::set<std::string> returns = {"void", "int", "double", "float", "bool", "auto", "char", "long", "unsigned", "I", ">", "*", "&"};
  std::set<std::string> names;
  for (size_t f = 0; f < files.size(); ++f) {
    const std::vector<Token>& t = files[f];
    const std::vector<size_t> closing = closingBrackets(t);
    for (size_t i = 1; i + 1 < t.size(); ++i) {
      if (t[i].text != "I" || t[i + 1].text != "(" || closing[i + 1] == SIZE_MAX) continue;
      size_t k = closing[i + 1] + 1;
      if (python[f]) {  // def NAME(...) [-> T]: [a docstring] [pass], then the next definition or the end
        if (t[i - 1].text != "def") continue;
        while (k < t.size() && t[k].text != ":" && t[k].line == t[i].line) ++k;
        size_t next = k + 1;
        while (next < t.size() && (t[next].text == "S" || t[next].text == "pass")) ++next;
        if (next == t.size() || t[next].text == "def" || t[next].text == "class" || t[next].text == "@") names.insert(t[i].raw);
        continue;
      }
      // C++: TYPE NAME(...) [const] [override] [noexcept] {}
      if (returns.count(t[i - 1].text) == 0) continue;
      while (k < t.size() && (t[k].text == "const" || t[k].text == "override" || (t[k].text == "I" && t[k].raw == "noexcept"))) ++k;
      if (k + 1 < t.size() && t[k].text == "{" && t[k + 1].text == "}") names.insert(t[i].raw);
    }
  }
  return std::vector<std::string>(names.begin(), names.end());
}

std::vector<Token> withoutDeadStatements(const std::vector<Token>& tokens, bool python, const std::vector<std::string>& unread,
                                         const std::vector<std::string>& empty_functions) {
  const std::unordered_set<std::string> dead(unread.begin(), unread.end());
  const std::unordered_set<std::string> empty(empty_functions.begin(), empty_functions.end());
  const std::vector<size_t> closing = closingBrackets(tokens);
  std::vector<Token> out;
  for (const Statement& s : statementsOf(tokens, python)) {
    const bool dead_store = !s.targets.empty() && std::all_of(s.targets.begin(), s.targets.end(), [&](const std::string& name) {
      return dead.count(name) != 0;
    });
    if (s.pure || dead_store || (!empty.empty() && callOf(tokens, s.begin, s.end, python, closing, empty))) {
      const size_t labels = pastAccessLabels(tokens, s.begin, s.end, python);
      out.insert(out.end(), tokens.begin() + static_cast<long>(s.begin), tokens.begin() + static_cast<long>(labels));
      continue;
    }
    out.insert(out.end(), tokens.begin() + static_cast<long>(s.begin), tokens.begin() + static_cast<long>(s.end));
  }
  return out;
}

}  // namespace aula::grade
