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

namespace {

// A statement: tokens [begin, end); `targets` the names it stores (none: it stores nothing).
struct Statement {
  size_t begin = 0, end = 0;
  std::vector<std::string> targets;
  bool pure = false;  // stores nothing, calls nothing: an expression whose value is dropped
};

bool isOpenBracket(const std::string& x) { return x == "(" || x == "[" || x == "{"; }
bool isCloseBracket(const std::string& x) { return x == ")" || x == "]" || x == "}"; }

// Where the name stored at `i` is followed by an assignment (`=`, `op=`, C++ `++`/`--`, or a
// declaration's end): the index past the operator, or 0 when it is no store.
size_t pastStore(const std::vector<Token>& t, size_t i, size_t end, bool python, bool declared) {
  auto is = [&](size_t k, const char* text) { return k < end && t[k].text == text; };
  if (declared && (is(i + 1, ";") || is(i + 1, ","))) return i + 1;
  if (is(i + 1, "=") && !is(i + 2, "=")) return i + 2;
  static const std::set<std::string> ops = {"+", "-", "*", "/", "%", "&", "|", "^"};
  size_t op = i + 1;
  while (op < end && op < i + 3 && ops.count(t[op].text) != 0) ++op;
  if (op > i + 1 && is(op, "=") && !is(op + 1, "=")) return op + 1;  // x += ..., x //= ..., x **= ...
  if (!python && ((is(i + 1, "+") && is(i + 2, "+")) || (is(i + 1, "-") && is(i + 2, "-"))) && is(i + 3, ";")) return i + 3;
  return 0;
}

// Where a statement's own tokens start, past what only labels it: C++ `public:` (and the other
// access specifiers), `default:`, `else`; Python `else:`. `private: double junk = 0;` stores junk.
// C++ access specifiers and `default:` alone: what a dropped statement leaves of itself (the
// class's layout is the original's).
size_t pastAccessLabels(const std::vector<Token>& t, size_t k, size_t end, bool python) {
  auto is = [&](size_t i, const char* text) { return i < end && t[i].text == text; };
  while (!python && (is(k, "public") || is(k, "private") || is(k, "protected") || is(k, "default")) && is(k + 1, ":")) k += 2;
  return k;
}

size_t pastLabels(const std::vector<Token>& t, size_t k, size_t end, bool python) {
  auto is = [&](size_t i, const char* text) { return i < end && t[i].text == text; };
  for (;;) {
    const size_t labels = pastAccessLabels(t, k, end, python);
    if (labels != k) {
      k = labels;
    } else if (is(k, "else")) {
      k += python && is(k + 1, ":") ? 2 : 1;
    } else {
      return k;
    }
  }
}

// The names `[k, end)` stores: `[type...] [this->|self.] NAME (= | op= | ++ | --) ...`, `++NAME;`,
// a C++ declaration of one or more names (`double a = 0, b;`), a Python tuple (`a, self.b = ...`).
std::vector<std::string> storedNames(const std::vector<Token>& t, size_t k, size_t end, bool python) {
  auto is = [&](size_t i, const char* text) { return i < end && t[i].text == text; };
  static const std::set<std::string> types = {"int", "double", "float", "bool", "auto", "char", "long", "unsigned", "const", "static"};
  size_t i = pastLabels(t, k, end, python);
  bool declared = false;
  if (!python) {
    while (i < end && types.count(t[i].text) != 0) ++i, declared = true;
    if (is(i, "I") && is(i + 1, "I")) ++i, declared = true;  // a type of the student's: `Point p = ...`
    if (((is(i, "+") && is(i + 1, "+")) || (is(i, "-") && is(i + 1, "-"))) && is(i + 2, "I") && is(i + 3, ";")) return {t[i + 2].raw};
  }
  std::vector<std::string> names;
  auto member = [&](size_t& at) {
    if (!python && is(at, "this") && is(at + 1, "-") && is(at + 2, ">")) at += 3;
    if (python && is(at, "self") && is(at + 1, ".")) at += 2;
  };
  member(i);
  if (!is(i, "I")) return {};
  if (python && is(i + 1, ",")) {  // a, self.b = ...
    while (is(i, "I")) {
      names.push_back(t[i].raw);
      if (is(i + 1, "=") && !is(i + 2, "=")) return names;
      if (!is(i + 1, ",")) return {};
      i += 2;
      member(i);
    }
    return {};
  }
  size_t past = pastStore(t, i, end, python, declared);
  if (past == 0) return {};
  names.push_back(t[i].raw);
  for (size_t next = past; is(next, "I") && is(next + 1, "=") && !is(next + 2, "="); next += 2) names.push_back(t[next].raw);  // a = b = 0
  if (!declared) return names;
  // A declaration's further names: after each comma at the top level, `NAME` then `=`, `,` or `;`.
  int depth = 0;
  for (size_t m = past - 1; m < end; ++m) {
    const std::string& x = t[m].text;
    depth += isOpenBracket(x) ? 1 : isCloseBracket(x) ? -1 : 0;
    if (depth == 0 && x == "," && is(m + 1, "I") && pastStore(t, m + 1, end, python, true) != 0) names.push_back(t[m + 1].raw);
  }
  return names;
}

// Whether `[k, end)` only computes a value and drops it: no store, no call, no keyword but a
// cast to void or literal ones.
bool pureExpression(const std::vector<Token>& t, size_t k, size_t end, bool python) {
  static const std::set<std::string> cpp_allowed = {"I", "N", "S", "true", "false", "nullptr", "this", "void", "+", "-", "*", "/",
                                                    "%", "<", ">", "!", "~", "&", "|", "^", "?", ":", ".", ",", "[", "]", "(", ")", ";"};
  static const std::set<std::string> py_allowed = {"I", "N", "S", "None", "True", "False", "self", "and", "or", "not", "in", "is",
                                                   "if", "else", "+", "-", "*", "/", "%", "<", ">", "!", "~", "&", "|", "^", ":",
                                                   ".", ",", "[", "]", "(", ")", "{", "}"};
  const auto& allowed = python ? py_allowed : cpp_allowed;
  if (k >= end || (python && (t[k].text == "if" || t[k].text == "else"))) return false;
  for (size_t i = k; i < end; ++i) {
    const std::string& x = t[i].text;
    if (allowed.count(x) == 0) return false;
    if ((x == "+" || x == "-") && i + 1 < end && t[i + 1].text == x) return false;  // ++, --
    if (x == "(" && i > k) {
      const std::string& before = t[i - 1].text;
      const bool cast = before == ")" && i >= k + 3 && t[i - 2].text == "void" && t[i - 3].text == "(";
      if ((before == "I" || before == ")" || before == "]" || before == "S" || before == ">") && !cast) return false;  // a call
    }
  }
  return true;
}

// Whether the name at `i`, inside `s`, is stored there and not read (`if (c) junk = 0;`, `f(x = 1)`):
// a plain name or a `this->`/`self.` member followed by an assignment.
bool storedAt(const std::vector<Token>& t, size_t i, const Statement& s, bool python) {
  // A constructor's member initialiser (`: junk_(0), v_{1}`) stores its member.
  if (!python && i > s.begin && (t[i - 1].text == ":" || t[i - 1].text == ",") && i + 1 < s.end &&
      (t[i + 1].text == "(" || t[i + 1].text == "{")) {
    return true;
  }
  if (i > s.begin && t[i - 1].text == ".") {
    if (!(python && i >= s.begin + 2 && t[i - 2].text == "self")) return false;
  } else if (i > s.begin + 1 && t[i - 1].text == ">" && t[i - 2].text == "-") {
    if (!(i >= s.begin + 3 && t[i - 3].text == "this")) return false;
  }
  return pastStore(t, i, s.end, python, false) != 0;
}

// A store under an `if` of its own, with no block (`if (c) junk = 1;`, Python `if c: junk = 1`):
// the names it stores, so that it is as dead as they are; none for any other statement.
std::vector<std::string> guardedStore(const std::vector<Token>& t, size_t begin, size_t end, bool python) {
  begin = pastLabels(t, begin, end, python);
  if (begin >= end || t[begin].text != "if") return {};
  int depth = 0;
  for (size_t i = begin + 1; i < end; ++i) {
    const std::string& x = t[i].text;
    depth += isOpenBracket(x) ? 1 : isCloseBracket(x) ? -1 : 0;
    const bool condition_ends = python ? (depth == 0 && x == ":") : (depth == 0 && x == ")");
    if (condition_ends) return i + 1 < end ? storedNames(t, i + 1, end, python) : std::vector<std::string>{};
  }
  return {};
}

// C++: statements end at `;` (outside brackets) or before `{`/`}`; Python: at a line's end
// outside brackets.
std::vector<Statement> statementsOf(const std::vector<Token>& t, bool python) {
  std::vector<Statement> out;
  size_t begin = 0;
  int depth = 0;
  auto close = [&](size_t end) {
    if (end > begin) {
      Statement s{begin, end, storedNames(t, begin, end, python), false};
      if (s.targets.empty()) s.targets = guardedStore(t, begin, end, python);
      const bool ends = python || t[end - 1].text == ";";
      s.pure = s.targets.empty() && ends && pureExpression(t, begin, end, python);
      if (!ends) s.targets.clear();  // a for's head `for (int i = 0`, `x = {`: never dropped
      out.push_back(s);
    }
    begin = end;
  };
  for (size_t i = 0; i < t.size(); ++i) {
    const std::string& x = t[i].text;
    if (python) {
      depth = std::max(0, depth + (isOpenBracket(x) ? 1 : isCloseBracket(x) ? -1 : 0));
      if (depth == 0 && (i + 1 == t.size() || t[i + 1].line != t[i].line)) close(i + 1);
      continue;
    }
    if (x == "(" || x == "[") ++depth;
    if ((x == ")" || x == "]") && depth > 0) --depth;
    if (depth > 0) continue;
    if (x == ";") {
      close(i + 1);
    } else if (x == "{" || x == "}") {
      close(i);
      close(i + 1);  // the brace alone: no store
    }
  }
  close(t.size());
  return out;
}

}  // namespace

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
