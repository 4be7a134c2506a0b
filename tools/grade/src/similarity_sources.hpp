#pragma once
// The class's code and the known algorithms' code, compared (similarity.hpp): what collect()
// (grades.cpp) writes to similarity.csv and shows in report.html. Private to tools/grade/src.

#include <aula/grade/similarity.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aula::grade {

// Compares `folders` (the students' hand-ins, each read whole) with each other and with the
// known algorithms that ran (OUT/known: the built-ins and the teacher's --known `known_folders`);
// writes OUT/similarity.csv and returns report.html's section.
std::string compareSubmissions(const std::string& out_dir, const std::vector<std::string>& folders, const std::string& exercise,
                               std::vector<nlohmann::json> results, const SimilarityRules& rules,
                               const std::vector<std::string>& known_folders);

}  // namespace aula::grade
