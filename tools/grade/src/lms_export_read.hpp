#pragma once
// Internal to aula_grade: an LMS's export read (lms_export_read.cpp), for readHandIns and
// exportLayout (lms_export.cpp).

#include <aula/grade/hand_in.hpp>
#include <aula/grade/lms_export.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace aula::grade::detail {

// One student of an export, with their items (what they handed in).
struct ExportStudent {
  Student student;
  std::vector<HandInItem> items;
};

// An export zip unpacked has its class either at its top or in one folder (a zip of the folder).
std::filesystem::path classFolder(const std::filesystem::path& folder);

// The layout of the class's folder: "moodle", "canvas", or "" for neither.
std::string layoutOfFolder(const std::filesystem::path& folder);

// A name as a folder of the grade's: ASCII letters and digits, the rest as '_', at most 40.
std::string folderWord(const std::string& name);

// The students of a Moodle or a Canvas export; throws config::ConfigError for an entry that is
// not the export's.
std::vector<ExportStudent> readMoodle(const std::filesystem::path& folder);
std::vector<ExportStudent> readCanvas(const std::filesystem::path& folder);

}  // namespace aula::grade::detail
