// lcmbus::UdpmReceiver and LcmDatagramAssembler: LCM's wire format read on the caller's thread,
// from a stock lcm::LCM publisher (short messages and fragmented long ones), Bus::hold, and the
// doorbell (Bus::deferWakeUps, Bus::wakeForTicksFrom).
#include <aula/lcm/bus.hpp>
#include <aula/lcm/udpm_receiver.hpp>

#include <aula/config/config.hpp>
#include <aula/motors_t.hpp>
#include <aula/sim_clock_t.hpp>

#include <poll.h>

#include <gtest/gtest.h>

#include "../../free_udp_port.hpp"

#include <chrono>
#include <cstring>
#include <thread>
#include <string>
#include <vector>

namespace {

using aula::lcmbus::LcmDatagramAssembler;
using aula::lcmbus::LcmMessage;

std::string privateUrl() {
  static const int port = aula::testing::freeUdpPort();
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

std::vector<uint8_t> bytesOf(std::initializer_list<uint32_t> words, const std::string& tail) {
  std::vector<uint8_t> bytes;
  for (uint32_t w : words) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<uint8_t>(w >> shift));
  }
  bytes.insert(bytes.end(), tail.begin(), tail.end());
  return bytes;
}

// A long message's fragment: magic, sequence, size, offset, then fragment number and count.
std::vector<uint8_t> fragment(uint32_t sequence, uint32_t size, uint32_t offset, uint16_t number, uint16_t count,
                              const std::string& tail) {
  return bytesOf({0x4c433033, sequence, size, offset, (uint32_t{number} << 16) | count}, tail);
}

std::string textOf(const LcmMessage& m) { return std::string(reinterpret_cast<const char*>(m.data), m.size); }

TEST(LcmDatagramAssembler, AShortMessageIsOneDatagram) {
  LcmDatagramAssembler assembler;
  const auto datagram = bytesOf({0x4c433032, 7}, std::string("ROOMBA_POSE\0payload", 19));
  const auto message = assembler.add(datagram.data(), datagram.size(), 1);
  ASSERT_TRUE(message);
  EXPECT_STREQ(message->channel, "ROOMBA_POSE");
  EXPECT_EQ(textOf(*message), "payload");
}

TEST(LcmDatagramAssembler, FragmentsOfALongMessageAreJoinedPerSender) {
  LcmDatagramAssembler assembler;
  const auto first = fragment(3, 10, 0, 0, 3, std::string("MAP\0abcd", 8));
  const auto second = fragment(3, 10, 4, 1, 3, "efg");
  const auto third = fragment(3, 10, 7, 2, 3, "hij");
  const auto other_sender = bytesOf({0x4c433032, 1}, std::string("X\0y", 3));
  EXPECT_FALSE(assembler.add(first.data(), first.size(), 1));
  EXPECT_TRUE(assembler.add(other_sender.data(), other_sender.size(), 2)) << "another sender's message in between";
  EXPECT_FALSE(assembler.add(second.data(), second.size(), 1));
  const auto message = assembler.add(third.data(), third.size(), 1);
  ASSERT_TRUE(message);
  EXPECT_STREQ(message->channel, "MAP");
  EXPECT_EQ(textOf(*message), "abcdefghij");
}

TEST(LcmDatagramAssembler, ALostFragmentLosesItsMessageOnly) {
  LcmDatagramAssembler assembler;
  const auto first = fragment(3, 10, 0, 0, 3, std::string("MAP\0abcd", 8));
  const auto third = fragment(3, 10, 7, 2, 3, "hij");
  const auto next_first = fragment(4, 4, 0, 0, 1, std::string("MAP\0wxyz", 8));
  EXPECT_FALSE(assembler.add(first.data(), first.size(), 1));
  EXPECT_FALSE(assembler.add(third.data(), third.size(), 1)) << "fragment 2 of 3 never came";
  const auto message = assembler.add(next_first.data(), next_first.size(), 1);
  ASSERT_TRUE(message) << "the next message replaces the unfinished one";
  EXPECT_EQ(textOf(*message), "wxyz");
}

TEST(LcmDatagramAssembler, MalformedDatagramsAreCountedAndIgnored) {
  LcmDatagramAssembler assembler;
  const auto no_magic = bytesOf({0x12345678, 1}, std::string("A\0b", 3));
  const auto no_nul = bytesOf({0x4c433032, 1}, "CHANNEL_WITHOUT_END");
  const auto too_short = bytesOf({0x4c433032}, "");
  const auto beyond = fragment(5, 4, 2, 0, 1, std::string("MAP\0abcd", 8));  // 4 bytes at offset 2 of 4
  for (const auto* d : {&no_magic, &no_nul, &too_short, &beyond}) EXPECT_FALSE(assembler.add(d->data(), d->size(), 1));
  EXPECT_EQ(assembler.malformed(), 4);
}

TEST(UdpmReceiver, AMalformedUrlNamesWhatIsWrong) {
  try {
    aula::lcmbus::parseUdpmUrl("udpm://239.255.76.67:7667?ttl=0&recv_buf_size=lots");
    FAIL() << "no error";
  } catch (const aula::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("recv_buf_size 'lots'"), std::string::npos) << e.what();
  }
  const auto url = aula::lcmbus::parseUdpmUrl("udpm://239.1.2.3:9000?ttl=1&recv_buf_size=4194304");
  EXPECT_EQ(url.group, "239.1.2.3");
  EXPECT_EQ(url.port, 9000);
  EXPECT_EQ(url.recv_buf_size, 4194304);
}

struct Collect {
  std::vector<std::string> seen;
  void on(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    seen.push_back(channel + ":" + std::string(static_cast<const char*>(buffer->data), buffer->data_size));
  }
};

TEST(UdpmReceiver, ABusGetsAStockPublishersLongAndShortMessagesInOrder) {
  aula::lcmbus::Bus bus(privateUrl());
  Collect collect;
  bus.subscribe("BIG", &Collect::on, &collect);
  bus.subscribe("SMALL", &Collect::on, &collect);
  lcm::LCM stock(privateUrl());
  std::string big(200000, 'x');  // more than one datagram: LCM sends it in fragments
  for (std::size_t i = 0; i < big.size(); i += 997) big[i] = static_cast<char>('a' + i % 26);
  stock.publish("SMALL", "one", 3);
  stock.publish("BIG", big.data(), static_cast<unsigned int>(big.size()));
  stock.publish("SMALL", "two", 3);
  for (int i = 0; i < 3; ++i) ASSERT_EQ(bus.handleTimeout(1000), 1);
  EXPECT_EQ(collect.seen, (std::vector<std::string>{"SMALL:one", "BIG:" + big, "SMALL:two"}));
  EXPECT_EQ(bus.handled(), 3);
}

TEST(UdpmReceiver, HeldPublicationsGoOutOnFlushInOrder) {
  aula::lcmbus::Bus publisher(privateUrl());
  aula::lcmbus::Bus subscriber(privateUrl());
  Collect collect;
  subscriber.subscribe("A", &Collect::on, &collect);
  subscriber.subscribe("B", &Collect::on, &collect);
  publisher.hold();
  publisher.publish("A", "1", 1);
  publisher.publish("B", "2", 1);
  publisher.publish("A", "3", 1);
  EXPECT_EQ(subscriber.handleTimeout(200), 0) << "nothing leaves while held";
  EXPECT_EQ(publisher.flush(), 0);
  for (int i = 0; i < 3; ++i) ASSERT_EQ(subscriber.handleTimeout(1000), 1);
  EXPECT_EQ(collect.seen, (std::vector<std::string>{"A:1", "B:2", "A:3"}));
  publisher.publish("B", "4", 1);  // after the flush, straight out again
  ASSERT_EQ(subscriber.handleTimeout(1000), 1);
  EXPECT_EQ(collect.seen.back(), "B:4");
}

bool readableWithin(int fd, int wall_ms) {
  pollfd readable{fd, POLLIN, 0};
  return poll(&readable, 1, wall_ms) > 0;
}

void publishTick(aula::lcmbus::Bus& bus, int64_t utime) {
  aula::sim_clock_t tick{};
  tick.utime = utime;
  bus.publish(aula::lcmbus::kClockChannel, &tick);
}

struct Log {
  std::vector<std::string> seen;
  void raw(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    seen.push_back(channel + ":" + std::string(static_cast<const char*>(buffer->data), buffer->data_size));
  }
  void tick(const lcm::ReceiveBuffer*, const std::string& channel, const aula::sim_clock_t* msg) {
    seen.push_back(channel + ":" + std::to_string(msg->utime));
  }
};

TEST(UdpmReceiver, DeferredChannelsWaitInOrderUntilADueTickWakesTheProcess) {
  aula::lcmbus::Bus simulator(privateUrl());
  aula::lcmbus::Bus referee(privateUrl());
  Log log;
  referee.subscribe("POSE", &Log::raw, &log);
  referee.subscribe("EPISODE", &Log::raw, &log);
  referee.subscribe(aula::lcmbus::kClockChannel, &Log::tick, &log);
  referee.deferWakeUps("POSE");
  referee.wakeForTicksFrom(2000000);

  simulator.publish("POSE", "1", 1);
  simulator.publish("POSE", "2", 1);
  publishTick(simulator, 1000000);
  EXPECT_FALSE(readableWithin(referee.getFileno(), 300)) << "poses and a tick before 2 s do not wake the referee";
  EXPECT_TRUE(log.seen.empty());
  simulator.publish("POSE", "3", 1);
  publishTick(simulator, 2000000);
  ASSERT_TRUE(readableWithin(referee.getFileno(), 1000)) << "the due tick wakes it";
  while (referee.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(log.seen, (std::vector<std::string>{"POSE:1", "POSE:2", "SIM_CLOCK:1000000", "POSE:3", "SIM_CLOCK:2000000"}))
      << "everything, in the order it was sent";
  EXPECT_FALSE(readableWithin(referee.getFileno(), 100)) << "nothing left to wake it";

  // A channel that is not deferred wakes it at once, and brings what waited before it.
  simulator.publish("POSE", "4", 1);
  simulator.publish("EPISODE", "e", 1);
  ASSERT_TRUE(readableWithin(referee.getFileno(), 1000));
  while (referee.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(log.seen.size(), 7u);
  EXPECT_EQ(log.seen[5], "POSE:4");
  EXPECT_EQ(log.seen[6], "EPISODE:e");

  // A wait with a timeout reads what is deferred when it times out, as a referee's housekeeping does.
  simulator.publish("POSE", "5", 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  while (referee.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(log.seen.back(), "POSE:5");
  EXPECT_EQ(referee.handled(), 8);
}

TEST(UdpmReceiver, AComponentWokenOnlyForTicksReadsItsSensorsWithEachTick) {
  aula::lcmbus::Bus simulator(privateUrl());
  aula::lcmbus::Bus component(privateUrl());
  Log log;
  component.subscribe("LASER", &Log::raw, &log);
  component.subscribe("POSE", &Log::raw, &log);
  component.subscribe(aula::lcmbus::kClockChannel, &Log::tick, &log);
  component.wakeOnlyFor({aula::lcmbus::kClockChannel});
  component.wakeForTicksFrom(5000000);  // its LockstepClient's next due tick: every tick wakes it still

  simulator.hold();
  simulator.publish("POSE", "1", 1);
  simulator.publish("LASER", "a", 1);
  simulator.publish("POSE", "2", 1);
  EXPECT_EQ(simulator.flush(), 0);
  EXPECT_FALSE(readableWithin(component.getFileno(), 300)) << "a burst's sensor messages do not wake it";
  EXPECT_TRUE(log.seen.empty());
  simulator.hold();
  simulator.publish("POSE", "3", 1);
  publishTick(simulator, 80000);
  EXPECT_EQ(simulator.flush(), 0);
  ASSERT_TRUE(readableWithin(component.getFileno(), 1000)) << "the tick, the burst's last datagram, wakes it";
  while (component.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(log.seen, (std::vector<std::string>{"POSE:1", "LASER:a", "POSE:2", "POSE:3", "SIM_CLOCK:80000"}))
      << "everything, in the order it was sent";
}

}  // namespace
