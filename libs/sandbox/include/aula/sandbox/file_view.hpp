#pragma once
// A process's view of the files, narrowed for the rest of its life (Landlock): it may read (and
// run) what is beneath `readable`, read and write what is beneath `writable`, and open nothing
// else (EACCES), whatever the mounts around it show. The algorithm's own process in a graded run
// takes it before loading the student's code: the run's world, bound in the sandbox for the
// component, is then out of the algorithm's reach, as are the parsed world's cache and the
// component's settings.

#include <string>
#include <vector>

namespace aula::sandbox {

struct FileView {
  std::vector<std::string> readable;  // folders or files: read, list, run
  std::vector<std::string> writable;  // folders or files: all of the above, and write, make, remove
};

// Narrows this process's (and its future children's) view to `view`. A path that does not exist
// is left out. Returns "" when done, else why not (a kernel without Landlock: the caller says so
// and goes on with the sandbox's own view).
std::string narrowFileView(const FileView& view);

}  // namespace aula::sandbox
