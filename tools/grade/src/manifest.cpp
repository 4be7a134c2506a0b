// The grading manifest's file (manifest.json): every planned run, and what collecting needs
// (the class's folders and similarity rules when similarity is on).
#include "aula/grade/grade_plan.hpp"

#include <aula/config/config.hpp>
#include <aula/config/paths.hpp>

#include <filesystem>
#include <fstream>

namespace aula::grade {
namespace fs = std::filesystem;
using config::ConfigError;

nlohmann::ordered_json Manifest::toJson() const {
  nlohmann::ordered_json json;
  json["exercise"] = exercise;
  json["out_dir"] = out_dir;
  if (similarity_rules) {
    json["similarity"] = {{"submissions", submissions},
                          {"known", known},
                          {"code_threshold", similarity_rules->code_threshold},
                          {"code_min_shared", similarity_rules->code_min_shared},
                          {"behaviour_threshold_m", similarity_rules->behaviour_threshold_m},
                          {"moved_m", similarity_rules->moved_m}};
  }
  json["runs"] = nlohmann::ordered_json::array();
  for (const PlannedRun& r : runs) {
    json["runs"].push_back({{"index", r.index},
                            {"student", r.student},
                            {"world", r.world_name},
                            {"world_sha256", r.world_sha256},
                            {"seed", r.seed},
                            {"plugin", r.plugin},
                            {"plugin_sha256", r.plugin_sha256},
                            {"language", r.language},
                            {"compile_error", r.compile_error},
                            {"build_machine", r.build_machine},
                            {"command", r.argv},
                            {"settings", r.settings},
                            {"result", r.result_path},
                            {"report", r.report_path},
                            {"log", r.log_path},
                            {"wall_limit_s", r.wall_limit_s}});
  }
  return json;
}

Manifest Manifest::fromJson(const nlohmann::json& json) {
  Manifest m;
  m.exercise = json.at("exercise").get<std::string>();
  m.out_dir = json.at("out_dir").get<std::string>();
  if (json.contains("similarity")) {
    const auto& similarity = json.at("similarity");
    m.submissions = similarity.at("submissions").get<std::vector<std::string>>();
    if (similarity.contains("known")) m.known = similarity.at("known").get<std::vector<std::string>>();
    SimilarityRules rules;
    rules.code_threshold = similarity.at("code_threshold").get<double>();
    rules.code_min_shared = similarity.at("code_min_shared").get<size_t>();
    rules.behaviour_threshold_m = similarity.at("behaviour_threshold_m").get<double>();
    rules.moved_m = similarity.at("moved_m").get<double>();
    m.similarity_rules = rules;
  }
  for (const auto& j : json.at("runs")) {
    PlannedRun r;
    r.index = j.at("index").get<int>();
    r.student = j.at("student").get<std::string>();
    r.world_name = j.at("world").get<std::string>();
    r.world_sha256 = j.at("world_sha256").get<std::string>();
    r.seed = j.at("seed").get<long long>();
    r.plugin = j.at("plugin").get<std::string>();
    r.plugin_sha256 = j.at("plugin_sha256").get<std::string>();
    r.compile_error = j.at("compile_error").get<std::string>();
    r.build_machine = j.value("build_machine", false);
    r.language = j.value("language", std::string("C++"));
    r.argv = j.at("command").get<std::vector<std::string>>();
    r.settings = j.value("settings", std::vector<std::string>{});
    r.result_path = j.at("result").get<std::string>();
    r.report_path = j.at("report").get<std::string>();
    r.log_path = j.at("log").get<std::string>();
    r.wall_limit_s = j.at("wall_limit_s").get<double>();
    m.runs.push_back(r);
  }
  return m;
}

void Manifest::save(const std::string& path) const {
  fs::create_directories(fs::path(path).parent_path());
  config::writeFileAtomically(path, toJson().dump(2) + "\n", "the grading manifest");
}

Manifest Manifest::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot read the manifest");
  try {
    return fromJson(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(path + ": not an aula grade manifest: " + e.what());
  }
}

}  // namespace aula::grade
