#include "aula/grade/student_page.hpp"

#include <aula/grade/grade_plan.hpp>
#include <aula/world/world_spec.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

namespace aula::grade {
namespace fs = std::filesystem;

namespace {

bool quotes(const std::string& text, const std::string& source) {
  if (text.size() < kQuoteBytes || source.size() < kQuoteBytes) return false;
  // Every window of the text against the source: texts are short (a message), sources small (a world).
  for (size_t at = 0; at + kQuoteBytes <= text.size(); at += 1) {
    if (source.find(text.data() + at, 0, kQuoteBytes) != std::string::npos) return true;
  }
  return false;
}

// An absolute path (after a start, a space, a quote, '=' or '(') left as its file's name.
std::string withoutFolders(const std::string& text) {
  static const std::regex path(R"((^|[\s"'=(\[,])/(?:[^/\s"'()\[\],:]+/)+([^/\s"'()\[\],:]*))");
  return std::regex_replace(text, path, "$1$2");
}

template <typename Json>
void sanitize(Json& value, const std::vector<std::string>& withheld) {
  if (value.is_string()) {
    value = forTheStudent(value.template get<std::string>(), withheld);
  } else if (value.is_object() || value.is_array()) {
    for (auto& item : value) sanitize(item, withheld);
  }
}

}  // namespace

WorldTexts::WorldTexts(const std::string& out_dir) {
  const fs::path manifest_path = fs::path(out_dir) / "manifest.json";
  if (!fs::is_regular_file(manifest_path)) return;
  Manifest manifest;
  try {
    manifest = Manifest::load(manifest_path.string());
  } catch (const std::exception&) {
    return;
  }
  const std::string option = "--world=";
  for (const PlannedRun& run : manifest.runs) {
    for (const std::string& arg : run.argv) {
      if (arg.rfind(option, 0) == 0) world_of_log_[run.log_path] = arg.substr(option.size());
    }
  }
  for (const auto& [log, world] : world_of_log_) {
    if (texts_.count(world) != 0) continue;
    std::vector<std::string>& texts = texts_[world];
    try {
      for (const std::string& input : world::worldFilesOf(world).inputs) {
        std::ifstream in(input, std::ios::binary);
        texts.emplace_back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      }
    } catch (const std::exception&) {  // a world that no longer reads: the paths and the caps still apply
      texts.clear();
    }
  }
}

const std::vector<std::string>& WorldTexts::ofRun(const std::string& log) const {
  static const std::vector<std::string> none;
  const auto world = world_of_log_.find(log);
  if (world == world_of_log_.end()) return none;
  const auto texts = texts_.find(world->second);
  return texts == texts_.end() ? none : texts->second;
}

std::string forTheStudent(const std::string& text, const std::vector<std::string>& withheld) {
  for (const std::string& source : withheld) {
    if (quotes(text, source)) return "(withheld from the student's page: it quotes the run's world)";
  }
  std::string out = withoutFolders(text);
  if (out.size() > kStudentTextChars) {
    const size_t dropped = out.size() - kStudentTextChars;
    out = out.substr(0, kStudentTextChars) + "... (" + std::to_string(dropped) + " characters more)";
  }
  return out;
}

RunFiles forTheStudent(RunFiles run, const std::vector<std::string>& withheld) {
  // The referee's picture writes the algorithm's failure in full: not on the page when that text
  // is not the page's to show as it is.
  for (const char* key : {"algorithm_error", "failure", "aborted"}) {
    const auto text = run.report.find(key);
    if (text != run.report.end() && text->is_string() && forTheStudent(text->get<std::string>(), withheld) != text->get<std::string>()) {
      run.picture_png.clear();
    }
  }
  sanitize(run.report, withheld);
  run.title = forTheStudent(run.title, withheld);
  if (!run.trace_json.empty()) {
    nlohmann::ordered_json trace = nlohmann::ordered_json::parse(run.trace_json, nullptr, false);
    if (trace.is_discarded()) {
      run.trace_json.clear();  // not the referee's JSON: no player rather than its text
    } else {
      // Its texts (events, breakdown), not the referee's own data: the poses, the map and the
      // exercise's state (the vacuum's cleaned cells, one long string) are no one's words, and a
      // state cut at the text cap would paint a run that contradicts its mark.
      const nlohmann::ordered_json as_written = trace;
      for (auto& [key, value] : trace.items()) {
        if (key != "samples" && key != "map" && key != "state") sanitize(value, withheld);
      }
      // Unchanged, the referee's bytes as they are: the page then holds the grade's only copy.
      if (trace != as_written) run.trace_json = trace.dump();
    }
  }
  return run;
}

}  // namespace aula::grade
