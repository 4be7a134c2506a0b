#pragma once
// Zip files (minizip, Debian's libminizip-dev): a hand-in's zips unpacked without letting any
// entry out of the folder it goes into, and the zips `aula grade` writes (Moodle's feedback files).

#include <cstdint>
#include <string>
#include <vector>

namespace aula::grade {

struct UnzipLimits {
  uint64_t max_bytes = 0;  // what its entries may hold in all, as they are read (not as they say)
  uint64_t max_files = 0;  // its entries, folders included
  int max_depth = 0;       // folders deep
};

// Unpacks `zip` into the folder `into` (made if missing; it must hold nothing the zip names).
// Refused, with the entry and the reason, and `into` removed: an entry whose name is absolute or
// has a ".." part, a link or any entry that is not a file or a folder, an encrypted one, two
// entries of one name, more entries, bytes or depth than `limits`, a damaged zip.
// Returns "" or the reason ("../evil.py is outside the hand-in"). `bytes`, `files`: what it unpacked.
std::string unzipSafely(const std::string& zip, const std::string& into, const UnzipLimits& limits, uint64_t& bytes,
                        uint64_t& files);

// Whether the file starts as a zip does ("PK\3\4", or an empty zip's "PK\5\6").
bool looksLikeZip(const std::string& path);

struct ZipItem {
  std::string name;   // as stored: "Ada Lovelace_12_assignsubmission_file_/vacuum-seed1.html"
  std::string bytes;
  uint32_t unix_mode = 0100644;  // a link's is 0120777, its bytes the target (tests write hostile zips)
};
// Writes `items` into the zip `path` (deflated); throws std::runtime_error naming the file.
void writeZip(const std::string& path, const std::vector<ZipItem>& items);

}  // namespace aula::grade
