#include "similarity_sources.hpp"

#include <aula/config/paths.hpp>
#include <aula/grade/grade_plan.hpp>
#include <aula/grade/grades.hpp>
#include <aula/grade/submission_build.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

// Every source a folder holds that a grade takes (submissionFiles: a helper file is code too);
// none when the folder is refused or holds none.
std::vector<std::string> sourcesOf(const std::string& folder) {
  std::vector<std::string> sources;
  if (folder.empty()) return sources;
  const SubmissionFiles files = submissionFiles(folder);
  if (!files.refused.empty()) return sources;
  for (const std::string& name : files.sources) sources.push_back((fs::path(folder) / name).string());
  return sources;
}

// A built-in's installed sources: Aula's own files (links in the build tree, so not submissionFiles,
// which takes no link from a student).
std::vector<std::string> builtInSources(const std::string& folder) {
  std::vector<std::string> sources;
  std::error_code error;
  if (folder.empty()) return sources;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && isPlainSourceName(entry.path().filename().string())) sources.push_back(entry.path().string());
  }
  std::sort(sources.begin(), sources.end());
  return sources;
}

}  // namespace

std::string compareSubmissions(const std::string& out_dir, const std::vector<std::string>& folders, const std::string& exercise,
                               std::vector<nlohmann::json> results, const SimilarityRules& rules,
                               const std::vector<std::string>& known_folders) {
  std::vector<Submitted> students;
  for (const std::string& folder : folders) {
    std::vector<std::string> sources = sourcesOf(folder);
    if (!sources.empty()) students.push_back({fs::path(folder).filename().string(), std::move(sources)});
  }
  // The known algorithms that ran, each by its code too: the built-ins' installed sources
  // (builtInAlgorithms' folder) and the teacher's solutions.
  std::map<std::string, std::vector<std::string>> known_sources;
  for (const Submission& builtin : builtInAlgorithms(exercise)) known_sources[builtin.student] = builtInSources(builtin.folder);
  for (const std::string& folder : known_folders) known_sources["known '" + fs::path(folder).filename().string() + "'"] = sourcesOf(folder);
  std::set<std::string> known_names;
  for (const auto& r : readResults(out_dir, "known")) {
    const std::string name = r.value("student", std::string("?"));
    if (known_names.insert(name).second) students.push_back({name, known_sources[name], true});
    results.push_back(r);
  }
  // What everyone starts from is not a likeness: the exercise's templates, in both languages.
  std::vector<Fingerprint> starter;
  for (const char* file : {"MyAlgorithm.cpp", "MyAlgorithm.py"}) {
    std::ifstream in(config::dataPath("templates/" + exercise + "/" + file));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const CodeForm form : {CodeForm::AsWritten, CodeForm::Common}) {
      const auto prints = codeFingerprints(text, fs::path(file).extension() == ".py", form);
      starter.insert(starter.end(), prints.begin(), prints.end());
    }
  }
  const auto pairs = compareClass(students, results, starter, rules);
  config::writeFileAtomically((fs::path(out_dir) / "similarity.csv").string(), similarityCsv(pairs), "similarity");
  return similarityHtml(pairs, students, rules);
}

}  // namespace aula::grade
