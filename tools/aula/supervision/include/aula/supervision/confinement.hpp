#pragma once
// What a graded run's component may see (aula_sandbox's Confinement), derived from what the
// component opens (measured with strace on a headless run of each exercise): Aula's runtime (its
// program, lib/aula: the SDF reader, the Python host, the in-tree plugins; of the built-in
// algorithms under lib/aula/references, only the one the run runs), the run's settings
// file, the run's world and the model files it was read from, the parsed world's cache entry (at
// the private cache's path, so the component does not parse the SDF again), and the student's
// plugin or MyAlgorithm.py. Nothing else of Aula's data folder, the user's home or the class.

#include <aula/sandbox/sandbox.hpp>

#include <string>
#include <vector>

namespace aula::supervision {

struct ComponentFiles {
  std::string program;      // the component's executable
  std::vector<std::string> runtime;  // what <prefix>/lib/aula holds but its references/ folder
  std::string data_dir;     // <prefix>/share/aula (only its worlds/ folder is made, empty, inside)
  std::string cfg;          // the run's .cfg
  std::vector<std::string> world_inputs;  // the world file and its models
  std::string world_cache_entry;          // the host's parsed-world entry (a file), "" for none
  std::string world_cache_name;           // its name in a cache folder ("worlds/<key>.txt")
  std::string algorithm;    // the student's plugin or .py, or the built-in's plugin ("" for the template)
};

// A file of the launcher's own for the run's length (bound into the sandbox), removed after it.
class TemporaryFile {
 public:
  TemporaryFile() = default;
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  // Writes `content` into a new file in $TMPDIR and returns its path. Throws std::runtime_error.
  std::string write(const std::string& content);

 private:
  std::string path_;
};

sandbox::Confinement componentConfinement(const ComponentFiles& files, const sandbox::Limits& limits);

// The files of the component of `exercise` ("vacuum") in a run on `world` with settings file `cfg`
// and `algorithm` (a built-in's name, or a path): looks up the world's inputs and cache entry.
ComponentFiles componentFiles(const std::string& program, const std::string& exercise, const std::string& cfg,
                              const std::string& world, const std::string& algorithm);

}  // namespace aula::supervision
