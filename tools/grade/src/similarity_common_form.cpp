// Code similarity across the two languages: C++ and Python tokens in one form (similarity.hpp's
// commonForm), so that a line-by-line port shares its k-grams with the original.
#include "aula/grade/similarity.hpp"

#include <set>
#include <string>
#include <vector>

namespace aula::grade {
namespace {

bool tokenIs(const std::vector<Token>& t, size_t k, const char* text) { return k < t.size() && t[k].text == text; }

// The C++ tokens that name a declaration's type, read on the tokens as written: a name followed
// by another name (`Foo name`), or by `&`/`*` and a name then what ends a declaration (`Foo& a,`
// `Foo* p =`), at a statement's or a parameter list's start; with the qualifiers before it.
std::vector<bool> cppTypeNames(const std::vector<Token>& t) {
  static const std::set<std::string> starts = {";", "{", "}", "(", ",", "const", "static", "public", "private", "protected"};
  std::vector<bool> type(t.size(), false);
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i].text != "I") continue;
    size_t first = i;  // back over `A::B::`
    while (first >= 3 && tokenIs(t, first - 1, ":") && tokenIs(t, first - 2, ":") && (t[first - 3].text == "I" || t[first - 3].text == "std")) {
      first -= 3;
    }
    if (first > 0 && starts.count(t[first - 1].text) == 0) continue;
    size_t k = i + 1;
    while (tokenIs(t, k, "&") || tokenIs(t, k, "*")) ++k;
    if (!tokenIs(t, k, "I")) continue;
    const bool ends = tokenIs(t, k + 1, "=") || tokenIs(t, k + 1, ";") || tokenIs(t, k + 1, ",") || tokenIs(t, k + 1, ")") ||
                      tokenIs(t, k + 1, "{") || tokenIs(t, k + 1, "(") || tokenIs(t, k + 1, ":") || tokenIs(t, k + 1, "[");
    if (k > i + 1 && !ends) continue;  // `a * b + c`: arithmetic
    for (size_t m = first; m < k; ++m) type[m] = true;
  }
  return type;
}

// C++ to the common form.
std::vector<Token> cppCommon(const std::vector<Token>& t) {
  static const std::set<std::string> dropped = {"const", "static", "auto", "void", "bool", "int", "double", "float", "char",
                                                "long", "unsigned", "override", "virtual", "public", "private", "protected",
                                                "typename", "template", "(", ")", "{", "}", ";", ":"};
  const std::vector<bool> type = cppTypeNames(t);
  std::vector<Token> out;
  auto add = [&](const Token& token, const std::string& text) { out.push_back({text, token.line, token.raw}); };
  for (size_t i = 0; i < t.size(); ++i) {
    const std::string& x = t[i].text;
    if (type[i]) continue;
    if (tokenIs(t, i + 1, ":") && tokenIs(t, i + 2, ":")) {  // std::, component::: a qualifier
      i += 2;
    } else if (x == "this" && tokenIs(t, i + 1, "-") && tokenIs(t, i + 2, ">")) {
      i += 2;
    } else if (x == "I" && t[i].raw == "static_cast" && tokenIs(t, i + 1, "<")) {  // Python's int(x) is dropped too
      while (i < t.size() && t[i].text != ">") ++i;
    } else if (x == "&" && tokenIs(t, i + 1, "&")) {
      add(t[i++], "and");
    } else if (x == "|" && tokenIs(t, i + 1, "|")) {
      add(t[i++], "or");
    } else if (x == "-" && tokenIs(t, i + 1, ">")) {
      add(t[i++], ".");
    } else if (x == "!" && !tokenIs(t, i + 1, "=")) {
      add(t[i], "not");
    } else if (x == "true" || x == "false") {
      add(t[i], x == "true" ? "True" : "False");
    } else if (x == "nullptr") {
      add(t[i], "None");
    } else if (dropped.count(x) == 0) {
      add(t[i], x);
    }
  }
  return out;
}

// `a, b = x, y` as C++ writes it, `a = x, b = y` (`double a = x, b = y;`): a line of names, `=`
// and as many expressions at the top level.
std::vector<Token> splitTupleAssignments(const std::vector<Token>& t) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < t.size()) {
    size_t end = i;
    while (end < t.size() && t[end].line == t[i].line) ++end;
    std::vector<size_t> names;  // the left side: I , I , ... =
    size_t k = i;
    while (k + 1 < end && t[k].text == "I" && (t[k + 1].text == "," || t[k + 1].text == "=")) {
      names.push_back(k);
      k += 2;
      if (t[k - 1].text == "=") break;
    }
    std::vector<std::pair<size_t, size_t>> values;  // the right side's top-level expressions
    if (names.size() >= 2 && t[k - 1].text == "=" && !(k < end && t[k].text == "=")) {
      int depth = 0;
      size_t from = k;
      for (size_t m = k; m < end; ++m) {
        const std::string& x = t[m].text;
        depth += (x == "(" || x == "[" || x == "{") ? 1 : (x == ")" || x == "]" || x == "}") ? -1 : 0;
        if (depth == 0 && x == ",") {
          values.emplace_back(from, m);
          from = m + 1;
        }
      }
      values.emplace_back(from, end);
    }
    if (names.size() >= 2 && values.size() == names.size()) {
      for (size_t n = 0; n < names.size(); ++n) {
        if (n > 0) out.push_back({",", t[names[n]].line, ""});
        out.push_back(t[names[n]]);
        out.push_back({"=", t[names[n]].line, ""});
        out.insert(out.end(), t.begin() + static_cast<long>(values[n].first), t.begin() + static_cast<long>(values[n].second));
      }
    } else {
      out.insert(out.end(), t.begin() + static_cast<long>(i), t.begin() + static_cast<long>(end));
    }
    i = end;
  }
  return out;
}

// Python to the common form.
std::vector<Token> pythonCommon(const std::vector<Token>& tokens) {
  const std::vector<Token> t = splitTupleAssignments(tokens);
  static const std::set<std::string> dropped = {"def", "(", ")", ":", ";", "{", "}"};
  static const std::set<std::string> casts = {"int", "float", "bool", "str"};
  static const std::set<std::string> modules = {"math"};
  std::vector<Token> out;
  for (size_t i = 0; i < t.size(); ++i) {
    const Token& x = t[i];
    if ((x.text == "self" || (x.text == "I" && modules.count(x.raw) != 0)) && tokenIs(t, i + 1, ".")) {
      ++i;
      continue;
    }
    if (x.text == "self" && tokenIs(t, i + 1, ",")) {  // a method's first parameter: C++ has none
      ++i;
      continue;
    }
    if (x.text == "self" && tokenIs(t, i + 1, ")")) continue;
    if (x.text == "I" && casts.count(x.raw) != 0 && tokenIs(t, i + 1, "(")) continue;
    if (x.text == "elif") {
      out.push_back({"else", x.line, ""});
      out.push_back({"if", x.line, ""});
    } else if (dropped.count(x.text) == 0) {
      out.push_back(x);
    }
  }
  return out;
}

}  // namespace

std::vector<Token> commonForm(const std::vector<Token>& tokens, bool python) {
  return python ? pythonCommon(tokens) : cppCommon(tokens);
}

}  // namespace aula::grade
