// A process's descendants, read from /proc: children and grandchildren, and nothing when gone.
#include <aula/process/process_tree.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

namespace {

TEST(ProcessTree, ChildrenAndGrandchildrenAreCounted) {
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    // Two grandchildren that wait, then tell the test they are there.
    for (int i = 0; i < 2; ++i) {
      if (::fork() == 0) {
        ::pause();
        ::_exit(0);
      }
    }
    (void)!::write(ready[1], "x", 1);
    ::pause();
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  const auto below_me = aula::process::descendantsOf(::getpid());
  EXPECT_NE(std::find(below_me.begin(), below_me.end(), child), below_me.end());
  EXPECT_EQ(aula::process::descendantsOf(child).size(), 2u);
  for (pid_t pid : aula::process::descendantsOf(child)) ::kill(pid, SIGKILL);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  EXPECT_TRUE(aula::process::descendantsOf(child).empty());
  ::close(ready[0]);
  ::close(ready[1]);
}

}  // namespace
