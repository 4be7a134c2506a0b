// lcmbus::Bus: a process receives only what it subscribes to (a kernel socket filter on its
// receiving socket), on the thread that handles them, and a stock LCM client on the run's URL
// still sees every channel.
#include <aula/lcm/bus.hpp>
#include <aula/lcm/udpm_receiver.hpp>

#include <aula/config/config.hpp>
#include <aula/motors_t.hpp>
#include <aula/sim_clock_t.hpp>

#include <gtest/gtest.h>

#include "../../free_udp_port.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <linux/filter.h>
#include <sys/socket.h>
#include <unistd.h>

#include <regex>
#include <string>

#include <chrono>
#include <cstring>
#include <vector>
#include <set>
#include <string>
#include <thread>

namespace {

using aula::lcmbus::Bus;

// This test process's private port (one the OS hands out).
int privatePort() {
  static const int port = aula::testing::freeUdpPort();
  return port;
}

std::string privateUrl() { return "udpm://239.255.76.67:" + std::to_string(privatePort()) + "?ttl=0"; }

struct Count {
  int messages = 0;
  void on(const lcm::ReceiveBuffer*, const std::string&, const aula::motors_t*) { ++messages; }
};

// Handles whatever arrives within `wall_ms`; returns how many packets the bus handed over
// (LCM's handle() returns for every packet received, subscribed to or not).
int packetsWithin(Bus& bus, int wall_ms) {
  int packets = 0;
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(wall_ms);
  while (std::chrono::steady_clock::now() < until) {
    if (bus.handleTimeout(10) > 0) ++packets;
  }
  return packets;
}

int packetsWithin(lcm::LCM& bus, int wall_ms) {
  int packets = 0;
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(wall_ms);
  while (std::chrono::steady_clock::now() < until) {
    if (bus.handleTimeout(10) > 0) ++packets;
  }
  return packets;
}

// The channel of a short LCM packet (after its 8-byte header), as the filter reads it.
std::string channelOf(const char* payload, ssize_t size) {
  if (size <= 8) return "";
  return std::string(payload + 8, strnlen(payload + 8, static_cast<std::size_t>(size - 8)));
}

// A plain socket on this test's group and port with `program` attached: what the kernel lets
// through it (-1 if it cannot be set up).
int filteredGroupSocket(const std::vector<aula::lcmbus::SocketFilterInstruction>& program) {
  const int raw = socket(AF_INET, SOCK_DGRAM, 0);
  if (raw < 0) return -1;
  const int yes = 1;
  setsockopt(raw, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(privatePort()));
  ip_mreq membership{};
  inet_pton(AF_INET, "239.255.76.67", &membership.imr_multiaddr);
  std::vector<sock_filter> instructions;
  for (const auto& i : program) instructions.push_back(sock_filter{i.code, i.jump_if_true, i.jump_if_false, i.value});
  sock_fprog filter{static_cast<unsigned short>(instructions.size()), instructions.data()};
  if (bind(raw, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      setsockopt(raw, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0 ||
      setsockopt(raw, SOL_SOCKET, SO_ATTACH_FILTER, &filter, sizeof filter) != 0) {
    close(raw);
    return -1;
  }
  return raw;
}

TEST(Bus, TheChannelFilterPassesExactlyItsChannels) {
  const int raw = filteredGroupSocket(aula::lcmbus::channelFilter({"WANTED", "SIM_CLOCK"}));
  ASSERT_GE(raw, 0);

  lcm::LCM publisher(privateUrl());
  aula::motors_t command{};
  for (const char* channel : {"UNWANTED", "WANTE", "WANTED_TOO", "WANTED", "SIM_CLOC", "SIM_CLOCK", "XSIM_CLOCK", "wanted"}) {
    publisher.publish(channel, &command);
  }
  std::vector<std::string> passed;
  char payload[2000];
  timeval wait{0, 300000};
  setsockopt(raw, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
  for (ssize_t size; (size = recv(raw, payload, sizeof payload, 0)) > 0;) passed.push_back(channelOf(payload, size));
  close(raw);
  EXPECT_EQ(passed, (std::vector<std::string>{"WANTED", "SIM_CLOCK"}));
}

TEST(Bus, TheTickGatePassesOnlyTicksFromItsTime) {
  // A gate past 2^32 us: both halves of the 64-bit utime count.
  const int64_t gate_us = 5000000000;
  const int raw = filteredGroupSocket(aula::lcmbus::channelFilter({"OTHER", "SIM_CLOCK"}, aula::lcmbus::TickGate{"SIM_CLOCK", gate_us}));
  ASSERT_GE(raw, 0);

  lcm::LCM publisher(privateUrl());
  for (const int64_t utime : {int64_t{1000}, int64_t{1} << 32, gate_us - 1, gate_us, gate_us + 1, int64_t{9000000000},
                              (int64_t{1} << 33) - 1}) {
    aula::sim_clock_t tick{};
    tick.utime = utime;
    publisher.publish("SIM_CLOCK", &tick);
  }
  aula::motors_t command{};
  publisher.publish("OTHER", &command);
  std::vector<std::string> passed;
  char payload[2000];
  timeval wait{0, 300000};
  setsockopt(raw, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
  for (ssize_t size; (size = recv(raw, payload, sizeof payload, 0)) > 0;) {
    const std::string channel = channelOf(payload, size);
    if (channel != "SIM_CLOCK") {
      passed.push_back(channel);
      continue;
    }
    aula::sim_clock_t tick{};
    const int header = 8 + static_cast<int>(channel.size()) + 1;
    ASSERT_GE(tick.decode(payload + header, 0, static_cast<int>(size) - header), 0);
    passed.push_back(std::to_string(tick.utime));
  }
  close(raw);
  EXPECT_EQ(passed, (std::vector<std::string>{"5000000000", "5000000001", "9000000000", "8589934591", "OTHER"}));
}

TEST(Bus, AMalformedUrlIsAConfigError) {
  EXPECT_THROW(Bus("udpm://239.255.76.67:notaport?ttl=0"), aula::config::ConfigError);
  EXPECT_THROW(Bus("udpm://10.0.0.1:7667?ttl=0"), aula::config::ConfigError);
}

// This process's UDP sockets bound to `port`: each Bus's receiving socket on a udpm:// URL.
std::set<int> udpSocketsBoundTo(int port) {
  std::set<int> found;
  for (int fd = 0; fd < 1024; ++fd) {
    int type = 0;
    socklen_t type_size = sizeof type;
    sockaddr_in address{};
    socklen_t address_size = sizeof address;
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &type_size) != 0 || type != SOCK_DGRAM) continue;
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &address_size) != 0) continue;
    if (address.sin_family == AF_INET && ntohs(address.sin_port) == port) found.insert(fd);
  }
  return found;
}

// The socket filter on each of this process's UDP sockets bound to `port`: its length in
// instructions, 0 for none.
std::multiset<int> filtersOfSocketsOn(int port) {
  std::multiset<int> lengths;
  for (int fd : udpSocketsBoundTo(port)) {
    socklen_t length = 0;  // SO_GET_FILTER with no buffer: the program's length
    lengths.insert(getsockopt(fd, SOL_SOCKET, SO_GET_FILTER, nullptr, &length) == 0 ? static_cast<int>(length) : -1);
  }
  return lengths;
}

TEST(Bus, ABusReceivesOnlyTheChannelsItSubscribesTo) {
  const int port = privatePort();
  const std::string url = privateUrl();
  Bus publisher(url);
  Bus subscriber(url);
  Count wanted;
  subscriber.subscribe("WANTED", &Count::on, &wanted);
  const int filter_length = static_cast<int>(aula::lcmbus::channelFilter({"WANTED"}).size());
  const int empty_length = static_cast<int>(aula::lcmbus::channelFilter({}).size());
  EXPECT_EQ(filtersOfSocketsOn(port), (std::multiset<int>{empty_length, filter_length}))
      << "the publisher subscribes to nothing, the subscriber to WANTED only";

  aula::motors_t command{};
  for (int i = 0; i < 20; ++i) publisher.publish("UNWANTED", &command);
  publisher.publish("WANTED", &command);
  EXPECT_EQ(packetsWithin(subscriber, 300), 1);
  EXPECT_EQ(wanted.messages, 1);
}

TEST(Bus, AChannelNoLongerSubscribedIsDroppedByTheFilterAgain) {
  const int port = privatePort();
  const std::string url = privateUrl();
  Bus publisher(url);
  Bus subscriber(url);
  Count kept, left, listened;
  subscriber.listen("LISTENED");
  subscriber.subscribe("KEPT", &Count::on, &kept);
  lcm::Subscription* twice = subscriber.subscribe("KEPT", &Count::on, &kept);
  lcm::Subscription* gone = subscriber.subscribe("LEFT", &Count::on, &left);
  lcm::Subscription* heard = subscriber.subscribe("LISTENED", &Count::on, &listened);
  subscriber.unsubscribe(twice);  // KEPT has another subscription: still let through
  subscriber.unsubscribe(gone);
  subscriber.unsubscribe(heard);  // listened to before: still let through
  EXPECT_EQ(filtersOfSocketsOn(port),
            (std::multiset<int>{static_cast<int>(aula::lcmbus::channelFilter({}).size()),
                                static_cast<int>(aula::lcmbus::channelFilter({"KEPT", "LISTENED"}).size())}));

  aula::motors_t command{};
  for (int i = 0; i < 20; ++i) publisher.publish("LEFT", &command);
  publisher.publish("KEPT", &command);
  publisher.publish("LISTENED", &command);
  EXPECT_EQ(packetsWithin(subscriber, 300), 2) << "LEFT's twenty never reach the process";
  EXPECT_EQ(kept.messages, 1);
  EXPECT_EQ(left.messages, 0);
}

TEST(Bus, AStockClientOnTheRunsUrlSeesEveryChannel) {
  const std::string url = privateUrl();
  Bus publisher(url);
  lcm::LCM stock(url);  // what lcm-spy, lcm-logger or python-lcm open
  ASSERT_TRUE(stock.good());
  Count a, b;
  stock.subscribe("CHANNEL_A", &Count::on, &a);
  stock.subscribe("CHANNEL_B", &Count::on, &b);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));

  aula::motors_t command{};
  publisher.publish("CHANNEL_A", &command);
  publisher.publish("CHANNEL_B", &command);
  publisher.publish("CHANNEL_B", &command);
  packetsWithin(stock, 300);
  EXPECT_EQ(a.messages, 1);
  EXPECT_EQ(b.messages, 2);
}

TEST(Bus, ASubscriptionByPatternReceivesEveryChannel) {
  const std::string url = privateUrl();
  Bus publisher(url);
  Bus recorder(url);
  Count all;
  recorder.subscribe(".*", &Count::on, &all);
  EXPECT_EQ(filtersOfSocketsOn(privatePort()),
            (std::multiset<int>{0, static_cast<int>(aula::lcmbus::channelFilter({}).size())}))
      << "the recorder's socket has no filter";
  std::this_thread::sleep_for(std::chrono::milliseconds(50));

  aula::motors_t command{};
  publisher.publish("CHANNEL_A", &command);
  publisher.publish("CHANNEL_B", &command);
  packetsWithin(recorder, 300);
  EXPECT_EQ(all.messages, 2);
}

TEST(Bus, AnInProcessBusIsOnePlainLcm) {
  Bus bus("memq://");
  Count count;
  bus.subscribe("ANY", &Count::on, &count);
  aula::motors_t command{};
  bus.publish("ANY", &command);
  while (bus.handleTimeout(0) > 0) {
  }
  EXPECT_EQ(count.messages, 1);
}

}  // namespace

// Port 0 in a udpm:// URL (aula grade's runs): a port the OS hands out, the rest of the URL kept;
// any other URL as it is.
TEST(Bus, PortZeroBecomesAPortTheOsHandsOut) {
  const std::string url = aula::lcmbus::withFreePort("udpm://239.255.76.67:0?ttl=0&recv_buf_size=4194304");
  std::smatch m;
  ASSERT_TRUE(std::regex_match(url, m, std::regex(R"(udpm://239\.255\.76\.67:(\d+)\?ttl=0&recv_buf_size=4194304)"))) << url;
  const int port = std::stoi(m[1]);
  EXPECT_GT(port, 0);
  EXPECT_LT(port, 65536);
  EXPECT_TRUE(std::regex_match(aula::lcmbus::withFreePort("udpm://239.255.76.67:0"), std::regex(R"(udpm://239\.255\.76\.67:[1-9]\d*)")));
  for (const char* kept : {"udpm://239.255.76.67:7667?ttl=0", "udpm://239.255.76.67", "memq://", "file:///tmp/x.lcmlog"}) {
    EXPECT_EQ(aula::lcmbus::withFreePort(kept), kept);
  }
}

struct Recorded {
  std::vector<std::string> messages;  // channel, size and bytes' sum, in order
  void on(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    unsigned sum = 0;
    for (uint32_t i = 0; i < buffer->data_size; ++i) sum += static_cast<const uint8_t*>(buffer->data)[i];
    messages.push_back(channel + " " + std::to_string(buffer->data_size) + " " + std::to_string(sum));
  }
};

TEST(Bus, AHeldBurstArrivesWholeAndInOrderAtAStockClientAndABus) {
  // The burst goes out as LCM's own datagrams: short messages in one sendmmsg, a long one through
  // LCM's publish (its fragments), in the order they were published.
  const std::string url = privateUrl();
  Bus publisher(url);
  lcm::LCM stock(url);
  ASSERT_TRUE(stock.good());
  Recorded by_stock, by_bus;
  stock.subscribe("(FIRST|LONG|AFTER|LAST)", &Recorded::on, &by_stock);
  Bus subscriber(url);
  for (const char* channel : {"FIRST", "LONG", "AFTER", "LAST"}) subscriber.subscribe(channel, &Recorded::on, &by_bus);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));

  std::vector<uint8_t> small(100), large(20000);
  for (std::size_t i = 0; i < large.size(); ++i) large[i] = static_cast<uint8_t>(i * 7);
  for (std::size_t i = 0; i < small.size(); ++i) small[i] = static_cast<uint8_t>(i + 1);
  publisher.hold();
  publisher.publish("FIRST", small.data(), 100);
  publisher.publish("LONG", large.data(), 20000);
  publisher.publish("AFTER", small.data(), 60);
  publisher.publish("LAST", small.data(), 1);
  EXPECT_TRUE(by_bus.messages.empty());
  EXPECT_EQ(publisher.flush(), 0);
  const std::vector<std::string> expected = {"FIRST 100 5050", "LONG 20000 " + std::to_string([&] {
                                               unsigned sum = 0;
                                               for (uint8_t b : large) sum += b;
                                               return sum;
                                             }()),
                                             "AFTER 60 1830", "LAST 1 1"};
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while ((by_stock.messages.size() < 4 || by_bus.messages.size() < 4) && std::chrono::steady_clock::now() < until) {
    stock.handleTimeout(10);
    subscriber.handleTimeout(10);
  }
  EXPECT_EQ(by_stock.messages, expected);
  EXPECT_EQ(by_bus.messages, expected);
}

TEST(Bus, TheUrlsTimeToLiveIsANumberFrom0To255) {
  EXPECT_THROW(Bus("udpm://239.255.76.67:7667?ttl=many"), aula::config::ConfigError);
  EXPECT_THROW(Bus("udpm://239.255.76.67:7667?ttl=256"), aula::config::ConfigError);
  EXPECT_EQ(aula::lcmbus::parseUdpmUrl("udpm://239.255.76.67:7667?ttl=1").ttl, 1);
  EXPECT_EQ(aula::lcmbus::parseUdpmUrl("udpm://239.255.76.67:7667").ttl, 0);
}
