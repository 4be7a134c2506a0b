#pragma once
// A student's hand-in, as it came (a folder of theirs, or their files in an LMS's export): bounded
// before anything of it is copied, its zips unpacked safely, and the code to grade found in it
// (docs/grading.md, "From your LMS and back"). Everything in a hand-in is untrusted: its names are
// shown only through printableName, never followed as links, never let out of the hand-in.

#include <cstdint>
#include <string>
#include <vector>

namespace aula::grade {

// What one hand-in may hold, counted over everything in it, its zips' contents included: bytes
// (as the files say they are long, not as the disk holds them), files and folders, and depth.
// The defaults are the grade command's (tools/aula/commands/grade.cpp: --hand-in-size,
// --hand-in-files, --hand-in-depth); a scaffolded project with its build folder fits them.
struct HandInLimits {
  uint64_t max_bytes = 64ull << 20;
  uint64_t max_files = 2000;
  int max_depth = 12;
};

// A file is sparse when the disk holds less than a quarter of what it says it is long, past
// kSparseSlackBytes: 1 MiB that is 37 bytes on disk is refused, a compressed file system's
// source (a half or a third) is not.
constexpr uint64_t kSparseSlackBytes = 64u << 10;

// One thing handed in: its path here, and its name in the hand-in ("sub/MyAlgorithm.py"; for a
// plain student folder, "" is the folder itself).
struct HandInItem {
  std::string path;
  std::string name;
};

// "" when every item (a folder: everything under it) is a regular file or a folder, none sparse,
// and all of it within `limits`; else why not, naming the first file that is not:
// "refused: include/h0001.hpp is a sparse file (1048576 bytes, 4096 on disk)". Reads only the
// folders' listings and each file's status, and stops at the first file past a limit.
std::string checkHandIn(const std::vector<HandInItem>& items, const HandInLimits& limits);

// What was in a hand-in and what of it is graded.
struct StagedHandIn {
  std::vector<std::string> found;  // every file, as named in the hand-in (printable; a zip's as "a.zip: x.py")
  std::vector<std::string> taken;  // "MyAlgorithm.py (from sub/MyAlgorithm (1).py)"
  std::string refused;             // why nothing of it is graded ("nothing handed in", "refused: ..."), or ""
  std::string summary() const;     // one line for the student's row and page
};

// Stages `items`: checked (checkHandIn), copied into `as_found` (emptied first; each zip unpacked
// into a folder of its name, within what is left of `limits`), then the code to grade copied into
// `code` (emptied first), flat, under the names the grade builds: the latest MyAlgorithm.cpp or
// MyAlgorithm.py (a renamed copy, "MyAlgorithm (1).py", "MyAlgorithm-2.py", is a later one),
// searched for in every folder, with the sources beside it; else a single .cpp or .py of another
// name, taken as MyAlgorithm. `canvas_copies`: "NAME-N.ext" is a renamed copy of any source (the
// way Canvas names a resubmitted file), not only of MyAlgorithm.
StagedHandIn stageHandIn(const std::vector<HandInItem>& items, const std::string& as_found, const std::string& code,
                         const HandInLimits& limits, bool canvas_copies);

}  // namespace aula::grade
