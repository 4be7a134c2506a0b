#pragma once
// Internal to aula_grade: the steps hand_in.cpp and hand_in_code.cpp share.

#include <aula/grade/hand_in.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace aula::grade::detail {

// Copies the regular file `from` to `to`, at most `budget` bytes of it, never through a link;
// "" or why not.
std::string copyFile(const std::string& from, const std::string& to, uint64_t& budget);

bool endsWith(const std::string& text, const std::string& end);

// At most 8 names, printable, and how many more.
std::string listed(const std::vector<std::string>& names);

// Finds the code in `files` (under `root`), copies it into `code`; fills `staged`.
void takeCode(const std::filesystem::path& root, const std::vector<std::string>& files, const std::filesystem::path& code,
              bool canvas_copies, StagedHandIn& staged);

}  // namespace aula::grade::detail
