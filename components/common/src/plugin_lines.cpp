#include "aula/component/plugin_lines.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

// Nothing here allocates or takes a lock: a crash's signal handler runs it (see the header).
namespace aula::component {
namespace {

constexpr int kMaxFrames = 64;

void copyText(char* to, size_t size, const char* from, size_t n) {
  if (n >= size) n = size - 1;
  std::memcpy(to, from, n);
  to[n] = '\0';
}

void hexInto(char* out, uintptr_t value) {  // "0x1a2b"
  char digits[20];
  int n = 0;
  do {
    digits[n++] = "0123456789abcdef"[value & 0xf];
    value >>= 4;
  } while (value != 0);
  *out++ = '0';
  *out++ = 'x';
  while (n > 0) *out++ = digits[--n];
  *out = '\0';
}

bool startsWith(const char* text, size_t n, const char* prefix) {
  const size_t p = std::strlen(prefix);
  return n >= p && std::memcmp(text, prefix, p) == 0;
}

// addr2line -a -i -f -C on the offsets: its whole output in `out` ("" when it could not run).
size_t runAddr2line(const char* plugin, char (*offsets)[24], int count, char* out, size_t size) {
  const char* argv[8 + kMaxFrames] = {"addr2line", "-a", "-i", "-f", "-C", "-e", plugin};
  for (int i = 0; i < count; ++i) argv[7 + i] = offsets[i];
  argv[7 + count] = nullptr;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return 0;
  // vfork: no fork handlers and no malloc locks taken (the crash may have happened holding one).
  const pid_t child = ::vfork();
  if (child == 0) {
    ::dup2(fds[1], STDOUT_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, STDERR_FILENO);
    ::execv("/usr/bin/addr2line", const_cast<char* const*>(argv));
    ::_exit(127);
  }
  ::close(fds[1]);
  size_t used = 0;
  while (child > 0 && used + 1 < size) {
    const ssize_t n = ::read(fds[0], out + used, size - 1 - used);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    used += static_cast<size_t>(n);
  }
  ::close(fds[0]);
  int status = 0;
  while (child > 0 && ::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  out[used] = '\0';
  return child > 0 ? used : 0;
}

// "aula::vacuum::(anonymous namespace)::Segfault::execute(aula::vacuum::VacuumApi&) const" ->
// "Segfault::execute": no parameters, the last two names.
void shortFunction(const char* name, size_t n, char* out, size_t size) {
  if (startsWith(name, n, "??")) n = 0;
  size_t end = n;
  if (end >= 6 && std::memcmp(name + end - 6, " const", 6) == 0) end -= 6;
  if (end > 0 && name[end - 1] == ')') {  // the parameter list, found from its end
    int depth = 0;
    for (size_t i = end; i-- > 0;) {
      depth += name[i] == ')' ? 1 : name[i] == '(' ? -1 : 0;
      if (depth == 0) {
        end = i;
        break;
      }
    }
  }
  size_t from = 0, last = 0;  // the starts of the last two names, outside template arguments
  int angle = 0;
  for (size_t i = 0; i + 1 < end; ++i) {
    angle += name[i] == '<' ? 1 : name[i] == '>' ? -1 : 0;
    if (angle == 0 && name[i] == ':' && name[i + 1] == ':') {
      from = last;
      last = i + 2;
    }
  }
  copyText(out, size, name + from, end - from);
}

// One addr2line block (the lines after an "0x..." line): its first line in the student's file.
bool studentLineOf(const char* block, const char* block_end, StudentLine& line) {
  const char* function = nullptr;
  size_t function_n = 0;
  bool even = true;  // function, location, function, location...
  for (const char* at = block; at < block_end;) {
    const char* eol = static_cast<const char*>(std::memchr(at, '\n', static_cast<size_t>(block_end - at)));
    if (eol == nullptr) eol = block_end;
    const size_t n = static_cast<size_t>(eol - at);
    if (even) {
      function = at;
      function_n = n;
    } else if (!startsWith(at, n, "??") && !startsWith(at, n, "/usr/")) {
      // "/any/folder name/MyAlgorithm.cpp:10 (discriminator 2)": a folder's name may hold spaces,
      // so only a trailing " (...)" is cut off.
      size_t location_n = n;
      if (location_n > 0 && at[location_n - 1] == ')') {
        for (size_t i = location_n; i-- > 1;) {
          if (at[i] == '(' && at[i - 1] == ' ') {
            location_n = i - 1;
            break;
          }
        }
      }
      size_t base = location_n;  // the file's name: after the last '/'
      while (base > 0 && at[base - 1] != '/') --base;
      copyText(line.where, sizeof line.where, at + base, location_n - base);
      shortFunction(function, function_n, line.function, sizeof line.function);
      return true;
    }
    even = !even;
    at = eol + 1;
  }
  return false;
}

}  // namespace

bool PluginImage::holds(const void* address) const {
  const auto a = reinterpret_cast<uintptr_t>(address);
  return path[0] != '\0' && a >= begin && a < end;
}

int studentLines(const PluginImage& image, void* const* frames, int count, const void* exact, StudentLine* out,
                 int capacity) {
  struct stat st {};
  if (::stat(image.path, &st) != 0 ||
      static_cast<int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec != image.mtime_ns) {
    return 0;
  }
  char offsets[kMaxFrames][24];
  int n = 0;
  for (int i = 0; i < count && n < kMaxFrames; ++i) {
    if (!image.holds(frames[i])) continue;
    // A return address names the call before it: one byte back is inside that call.
    const uintptr_t back = frames[i] == exact ? 0 : 1;
    hexInto(offsets[n++], reinterpret_cast<uintptr_t>(frames[i]) - image.load_address - back);
  }
  if (n == 0) return 0;
  char output[16384];
  const size_t used = runAddr2line(image.path, offsets, n, output, sizeof output);
  int filled = 0;
  // Blocks start with the address itself ("0x..."), then function and location lines.
  const char* end = output + used;
  for (const char* at = output; at < end && filled < capacity;) {
    const char* block = static_cast<const char*>(std::memchr(at, '\n', static_cast<size_t>(end - at)));
    if (block == nullptr) break;
    ++block;
    const char* next = block;
    while (next < end && !startsWith(next, static_cast<size_t>(end - next), "0x")) {
      const char* eol = static_cast<const char*>(std::memchr(next, '\n', static_cast<size_t>(end - next)));
      next = eol == nullptr ? end : eol + 1;
    }
    if (studentLineOf(block, next, out[filled])) ++filled;
    at = next;
  }
  return filled;
}

}  // namespace aula::component
