// A process's narrowed view of the files (sandbox/file_view.hpp), in a child of its own (Landlock
// is for a process's life): beneath a readable folder it reads and lists, never writes; beneath
// a writable one it does both; anything else, even a file its owner may read, fails (EACCES).
#include <aula/sandbox/file_view.hpp>

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// Opens `path` with `flags` in the narrowed child: "ok", or the errno's name for EACCES.
std::string opened(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC, 0600);
  if (fd >= 0) {
    ::close(fd);
    return "ok";
  }
  return errno == EACCES ? "EACCES" : "errno " + std::to_string(errno);
}

}  // namespace

TEST(FileView, OnlyWhatItListsIsOpened) {
  const fs::path root = fs::temp_directory_path() / ("aula-file-view-" + std::to_string(::getpid()));
  fs::remove_all(root);
  for (const char* folder : {"readable", "writable", "hidden"}) {
    fs::create_directories(root / folder);
    std::ofstream(root / folder / "file") << "text";
  }
  int verdict[2];
  ASSERT_EQ(::pipe(verdict), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(verdict[0]);
    const std::string why = aula::sandbox::narrowFileView({{(root / "readable").string()}, {(root / "writable").string()}});
    std::string out;
    if (!why.empty()) {
      out = "skip: " + why;
    } else {
      out = opened((root / "readable" / "file").string(), O_RDONLY) + " " +
            opened((root / "readable" / "file").string(), O_WRONLY) + " " +
            opened((root / "readable" / "new").string(), O_WRONLY | O_CREAT) + " " +
            opened((root / "readable").string(), O_RDONLY | O_DIRECTORY) + " " +
            opened((root / "writable" / "file").string(), O_RDWR) + " " +
            opened((root / "writable" / "new").string(), O_WRONLY | O_CREAT) + " " +
            opened((root / "hidden" / "file").string(), O_RDONLY) + " " +
            opened((root / "hidden").string(), O_RDONLY | O_DIRECTORY) + " " +
            opened("/etc/hostname", O_RDONLY);  // a file anyone may read, outside the view
    }
    (void)!::write(verdict[1], out.data(), out.size());
    ::_exit(0);
  }
  ::close(verdict[1]);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::string out;
  char buffer[512];
  for (ssize_t n; (n = ::read(verdict[0], buffer, sizeof buffer)) > 0;) out.append(buffer, n);
  ::close(verdict[0]);
  fs::remove_all(root);
  if (out.rfind("skip: ", 0) == 0) GTEST_SKIP() << out;
  EXPECT_EQ(out, "ok EACCES EACCES ok ok ok EACCES EACCES EACCES");
}

// A path that does not exist is left out of the view, not an error.
TEST(FileView, AMissingPathIsLeftOut) {
  const pid_t child = ::fork();
  if (child == 0) {
    const std::string why = aula::sandbox::narrowFileView({{"/usr", "/no/such/folder"}, {}});
    ::_exit(why.empty() ? 0 : why.rfind("no Landlock", 0) == 0 ? 3 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 3) GTEST_SKIP() << "no Landlock in this kernel";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}
