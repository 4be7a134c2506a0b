// processGone: what the simulator asks of each client's pid when no launcher watches the run. A
// process that has exited is gone even before its parent reaps it (a zombie).
#include <aula/process/child_process.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

using aula::process::processGone;

TEST(ProcessGone, ALiveProcessIsNotGoneAndAnUnknownPidIsNeverGone) {
  EXPECT_FALSE(processGone(::getpid()));
  EXPECT_FALSE(processGone(1));  // init: alive (or one we may not signal)
  EXPECT_FALSE(processGone(0));
  EXPECT_FALSE(processGone(-1));
}

TEST(ProcessGone, AChildIsGoneOnceItExitedBeforeAndAfterItIsReaped) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::pause();  // until killed
    ::_exit(0);
  }
  EXPECT_FALSE(processGone(child));
  ::kill(child, SIGKILL);
  // A zombie until waitpid: gone already. Its state reaches /proc a moment after the signal.
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = processGone(child);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(gone);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(processGone(child));
}
