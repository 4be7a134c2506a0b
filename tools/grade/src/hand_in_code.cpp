// The code to grade found in a staged hand-in (hand_in.hpp): the student's MyAlgorithm, its
// latest copy, and the sources beside it.
#include "hand_in_code.hpp"

#include <aula/grade/submission_build.hpp>

#include <algorithm>
#include <map>
#include <regex>

namespace aula::grade::detail {
namespace fs = std::filesystem;

namespace {

// Not the student's code: a build's files, a Mac's resource forks, hidden files.
bool skipped(const std::string& relative) {
  for (const auto& part : fs::path(relative)) {
    const std::string p = part.string();
    if (p == "build" || p == "__MACOSX" || p == "__pycache__" || (!p.empty() && p[0] == '.')) return true;
  }
  return false;
}

// A file's name as the grade builds it, and which copy it is: "MyAlgorithm (2).py" is copy 2 of
// "MyAlgorithm.py"; "MyAlgorithm-1.py" copy 1 when `dash_copies`. The name itself is copy 0.
std::pair<std::string, int> copyOf(const std::string& file, bool dash_copies) {
  static const std::regex parens(R"(^(.+) \(([0-9]{1,6})\)(\.[A-Za-z]+)$)");
  static const std::regex dash(R"(^(.+)-([0-9]{1,6})(\.[A-Za-z]+)$)");
  std::smatch m;
  if (std::regex_match(file, m, parens) || (dash_copies && std::regex_match(file, m, dash))) {
    return {m[1].str() + m[3].str(), std::stoi(m[2].str())};
  }
  return {file, 0};
}

bool isSource(const std::string& name) {
  for (const char* ext : {".cpp", ".cc", ".cxx", ".hpp", ".h", ".hh", ".py"}) {
    if (endsWith(name, ext)) return true;
  }
  return false;
}

}  // namespace

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < names.size() && i < 8; ++i) text += (i == 0 ? "" : ", ") + printableName(names[i]);
  if (names.size() > 8) text += " and " + std::to_string(names.size() - 8) + " more";
  return text;
}

namespace {

struct Candidate {
  std::string file;  // relative to root
  int copy = 0;
};

// The file to grade in `files` and the name it is graded as ("MyAlgorithm.py"); false, with
// `staged.refused` saying why, when there is none or the student has not said which.
bool chooseMain(const std::vector<std::string>& files, std::string& main_file, std::string& main_name, StagedHandIn& staged) {
  std::map<std::string, std::vector<Candidate>> mains;  // "MyAlgorithm.cpp" / ".py" -> its copies
  std::vector<std::string> sources;
  for (const std::string& file : files) {
    if (skipped(file)) continue;
    const std::string base = fs::path(file).filename().string();
    const auto [name, copy] = copyOf(base, true);
    if (name == "MyAlgorithm.cpp" || name == "MyAlgorithm.py") mains[name].push_back({file, copy});
    if (endsWith(base, ".cpp") || endsWith(base, ".py")) sources.push_back(file);
  }
  if (mains.size() == 2) {
    staged.refused = "both MyAlgorithm.cpp and MyAlgorithm.py handed in: which one to grade is the student's to say";
    return false;
  }
  if (mains.size() == 1) {
    auto& copies = mains.begin()->second;
    std::sort(copies.begin(), copies.end(), [](const Candidate& a, const Candidate& b) { return a.copy > b.copy; });
    if (copies.size() > 1 && copies[0].copy == copies[1].copy) {
      staged.refused = "refused: " + printableName(copies[0].file) + " and " + printableName(copies[1].file) +
                       " are both the latest " + mains.begin()->first + ": which one to grade is the student's to say";
      return false;
    }
    main_file = copies[0].file;
    main_name = mains.begin()->first;
  } else if (sources.size() == 1) {
    main_file = sources[0];
    main_name = endsWith(main_file, ".py") ? "MyAlgorithm.py" : "MyAlgorithm.cpp";
  } else if (sources.empty()) {
    staged.refused = files.empty() ? "nothing handed in" : "no C++ or Python source handed in (found: " + listed(files) + ")";
    return false;
  } else {
    staged.refused = "no MyAlgorithm.cpp or MyAlgorithm.py, and " + std::to_string(sources.size()) + " sources (" +
                     listed(sources) + "): which one to grade is the student's to say";
    return false;
  }
  return true;
}

// The sources beside the main file, each at its latest copy; the main file's own copies are not among them.
std::map<std::string, Candidate> sourcesBeside(const std::vector<std::string>& files, const std::string& main_file,
                                               const std::string& main_name, bool canvas_copies) {
  const fs::path folder = fs::path(main_file).parent_path();
  std::map<std::string, Candidate> beside;
  for (const std::string& file : files) {
    if (fs::path(file).parent_path() != folder || file == main_file) continue;
    const auto [name, copy] = copyOf(fs::path(file).filename().string(), canvas_copies);
    if (!isSource(name) || copyOf(name, true).first == main_name) continue;
    auto it = beside.find(name);
    if (it == beside.end() || it->second.copy < copy) beside[name] = {file, copy};
  }
  return beside;
}

}  // namespace

void takeCode(const fs::path& root, const std::vector<std::string>& files, const fs::path& code, bool canvas_copies,
              StagedHandIn& staged) {
  std::string main_file, main_name;
  if (!chooseMain(files, main_file, main_name, staged)) return;
  const std::map<std::string, Candidate> beside = sourcesBeside(files, main_file, main_name, canvas_copies);
  std::error_code error;
  fs::create_directories(code, error);
  uint64_t budget = ~0ull;  // already bounded: they are files of the staged hand-in
  auto take = [&](const std::string& file, const std::string& as) {
    const std::string why = copyFile((root / file).string(), (code / as).string(), budget);
    if (!why.empty()) {
      staged.refused = "refused: " + printableName(file) + " " + why;
      return;
    }
    staged.taken.push_back(as == file ? as : as + " (from " + printableName(file) + ")");
  };
  take(main_file, main_name);
  for (const auto& [name, candidate] : beside) {
    if (staged.refused.empty()) take(candidate.file, name);
  }
}

}  // namespace aula::grade::detail
