#pragma once
// Where Aula's data lives, found at run time so the same binaries work from the build tree and
// from an install prefix: $AULA_DATA_DIR, else <folder of the executable>/../share/aula (the
// build tree has one too: symbolic links to the source's worlds/ and config/).

#include <cstdint>
#include <string>

namespace aula::config {

// The data folder (worlds/, config/); throws ConfigError naming what it tried.
std::string dataDir();
// Aula's own modules and plugins: <folder of the executable>/../lib/aula (a build tree has one
// too). Never throws: without /proc/self/exe, relative to the current folder.
std::string libDir();
// An exercise's built-in algorithm (a reference, a baseline: `--algorithm=NAME`), a plugin of its
// own: <libDir>/references/libaula_<exercise>_<name>.so. A graded run's sandbox binds only the one
// it runs (the references folder holds every exercise's references).
std::string builtinAlgorithmPath(const std::string& exercise, const std::string& name);
constexpr const char* kReferencesFolder = "references";  // under libDir()
// The user's documentation (grading.md, worlds.md, exercises/): <folder of the executable>/../share/doc/aula
// (installed by the .deb; a build tree links it to the source's docs/). Never throws.
std::string docDir();
// A data file: absolute as given, else relative to the data folder.
std::string dataPath(const std::string& relative);
// A world named on a command line or in a .cfg: an existing path as given (made absolute),
// else relative to the data folder, else a file name in <data>/worlds. Throws ConfigError
// ("`what`: no such world file ...") when none exists.
std::string resolveWorldPath(const std::string& value, const std::string& what);
// The per-user cache ($XDG_CACHE_HOME/aula, else ~/.cache/aula), created on demand.
std::string cacheDir();
// An output file given on a command line (`what`: "--report=out/r.json"): its folder must exist
// and be writable, checked before a run starts so a typo does not cost the whole run. Throws
// ConfigError naming the path and the folder.
void requireWritableFolder(const std::string& file_path, const std::string& what);
// Writes `content` to `path` whole or not at all (a temporary file beside it, renamed into place), so
// a reader never sees half a file. Throws std::runtime_error naming the path, `what` ("report")
// and the system's reason ("No space left on device").
void writeFileAtomically(const std::string& path, const std::string& content, const std::string& what);

// The whole of a small file a user names (a .cfg, a key, a result): refused at once with
// ConfigError (exit 2) naming `what` and the path when it is missing, a folder, not a regular
// file (a device such as /dev/zero, a FIFO: they may never end) or larger than `max_bytes`.
std::string readSmallFile(const std::string& path, uint64_t max_bytes, const std::string& what);

}  // namespace aula::config
