// Private to similarity: a source's statements as the dead-statement analysis reads them
// (similarity_statements.cpp parses, similarity_dead_code.cpp decides what is dead).
#pragma once

#include <string>
#include <vector>

#include "aula/grade/similarity.hpp"

namespace aula::grade::code_statements {

// A statement: tokens [begin, end); `targets` the names it stores (none: it stores nothing).
struct Statement {
  size_t begin = 0, end = 0;
  std::vector<std::string> targets;
  bool pure = false;  // stores nothing, calls nothing: an expression whose value is dropped
};

inline bool isOpenBracket(const std::string& x) { return x == "(" || x == "[" || x == "{"; }
inline bool isCloseBracket(const std::string& x) { return x == ")" || x == "]" || x == "}"; }

// Where a statement's own tokens start past C++ access specifiers and `default:` alone: what a
// dropped statement leaves of itself (the class's layout is the original's).
size_t pastAccessLabels(const std::vector<Token>& t, size_t k, size_t end, bool python);

// C++: statements end at `;` (outside brackets) or before `{`/`}`; Python: at a line's end
// outside brackets.
std::vector<Statement> statementsOf(const std::vector<Token>& t, bool python);

// Whether the name at `i`, inside `s`, is stored there and not read (`if (c) junk = 0;`, `f(x = 1)`).
bool storedAt(const std::vector<Token>& t, size_t i, const Statement& s, bool python);

}  // namespace aula::grade::code_statements
