// Similarity's statements: where each starts and ends, the names it stores, whether it only
// computes a value and drops it.
#include "similarity_statements.hpp"

#include <algorithm>
#include <set>

namespace aula::grade::code_statements {
namespace {

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

}  // namespace

// C++ access specifiers and `default:` alone: what a dropped statement leaves of itself (the
// class's layout is the original's).
size_t pastAccessLabels(const std::vector<Token>& t, size_t k, size_t end, bool python) {
  auto is = [&](size_t i, const char* text) { return i < end && t[i].text == text; };
  while (!python && (is(k, "public") || is(k, "private") || is(k, "protected") || is(k, "default")) && is(k + 1, ":")) k += 2;
  return k;
}

namespace {

// Where a statement's own tokens start, past what only labels it: C++ `public:` (and the other
// access specifiers), `default:`, `else`; Python `else:`. `private: double junk = 0;` stores junk.
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

}  // namespace

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

namespace {

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

}  // namespace

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

}  // namespace aula::grade::code_statements
