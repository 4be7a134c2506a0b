// The run's key travels over a pipe, and the tag it gives a message changes with every byte of
// the message and with the channel: a forger without the key cannot make one.
#include <aula/auth/run_key.hpp>
#include <aula/pose3d_t.hpp>
#include <aula/sim_control_t.hpp>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

namespace {

aula::pose3d_t pose(double x) {
  aula::pose3d_t msg{};
  msg.utime = 20000;
  msg.x = x;
  msg.y = 2.0;
  msg.q0 = 1.0;
  return msg;
}

}  // namespace

TEST(RunKey, TwoKeysDifferAndAPipeHandsOneOverWhole) {
  const aula::auth::Key key = aula::auth::randomKey();
  EXPECT_NE(key, aula::auth::randomKey());
  const int fd = aula::auth::keyPipe(key);
  EXPECT_TRUE(fcntl(fd, F_GETFD) & FD_CLOEXEC) << "no child inherits it unless handed it";
  EXPECT_EQ(aula::auth::readKey(fd, "test"), key);
}

TEST(RunKey, ADescriptorThatHoldsAnythingButOneKeyIsRefused) {
  int ends[2];
  ASSERT_EQ(pipe(ends), 0);
  ASSERT_EQ(write(ends[1], "short", 5), 5);
  close(ends[1]);
  EXPECT_THROW(aula::auth::readKey(ends[0], "--key-fd"), std::runtime_error);
  EXPECT_THROW(aula::auth::readKey(1000, "--key-fd"), std::runtime_error) << "not open";
  ASSERT_EQ(pipe(ends), 0);
  const std::string long_key(40, 'k');
  ASSERT_EQ(write(ends[1], long_key.data(), long_key.size()), 40);
  close(ends[1]);
  EXPECT_THROW(aula::auth::readKey(ends[0], "--key-fd"), std::runtime_error);
}

TEST(RunKey, ATagHoldsForItsMessageItsChannelAndItsKeyOnly) {
  const aula::auth::Key key = aula::auth::randomKey();
  aula::pose3d_t msg = pose(1.0);
  msg.auth_seq = 7;
  aula::auth::sign(aula::auth::Signer(key), "ROOMBA_POSE", msg);
  EXPECT_TRUE(aula::auth::verify(aula::auth::Signer(key), "ROOMBA_POSE", msg));
  EXPECT_FALSE(aula::auth::verify(aula::auth::Signer(key), "TAXI_POSE", msg)) << "replayed on another channel";
  EXPECT_FALSE(aula::auth::verify(aula::auth::Signer(aula::auth::randomKey()), "ROOMBA_POSE", msg));
  aula::pose3d_t moved = msg;
  moved.x = 1.0000001;
  EXPECT_FALSE(aula::auth::verify(aula::auth::Signer(key), "ROOMBA_POSE", moved));
  aula::pose3d_t renumbered = msg;
  renumbered.auth_seq = 8;
  EXPECT_FALSE(aula::auth::verify(aula::auth::Signer(key), "ROOMBA_POSE", renumbered)) << "the sequence number is covered too";
  aula::pose3d_t unsigned_msg = pose(1.0);
  unsigned_msg.auth_seq = 7;
  EXPECT_FALSE(aula::auth::verify(aula::auth::Signer(key), "ROOMBA_POSE", unsigned_msg));
}

TEST(RunKey, TheStamperNumbersEachChannelAndSignsOnlyWithAKey) {
  const aula::auth::Key key = aula::auth::randomKey();
  aula::auth::Stamper keyed(key);
  aula::auth::Stamper plain;
  aula::pose3d_t a = pose(1.0), b = pose(2.0), c = pose(3.0);
  keyed.stamp("ROOMBA_POSE", a);
  keyed.stamp("ROOMBA_POSE", b);
  keyed.stamp("TAXI_POSE", c);
  EXPECT_EQ(a.auth_seq, 1);
  EXPECT_EQ(b.auth_seq, 2);
  EXPECT_EQ(c.auth_seq, 1);
  EXPECT_TRUE(aula::auth::verify(aula::auth::Signer(key), "ROOMBA_POSE", b));
  aula::sim_control_t control{};
  plain.stamp("SIM_CONTROL", control);
  EXPECT_EQ(control.auth_seq, 1);
  for (uint8_t byte : control.auth) EXPECT_EQ(byte, 0) << "no key, no tag: the messages stay as they were";
}
