// What signing the lockstep costs per control period in a graded run: the component signs its
// ack (auth::clientKey's Signer) and the simulator checks it, beside the ack as it was (encoded
// only, which publishing does anyway). A 900 s vacuum run acks 11,250 control periods of the
// component and 900 of the referee.
#include <aula/auth/run_key.hpp>
#include <aula/lockstep_ack_t.hpp>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

const char* kChannel = "SIM_LOCKSTEP_ACK";

aula::lockstep_ack_t ackAt(int64_t seq) {
  aula::lockstep_ack_t ack{};
  ack.client = "vacuum-cleaner";
  ack.seq = seq;
  ack.utime = seq * 20000;
  return ack;
}

// The ack as it was: encoded for the bus.
void BM_AckUnsigned(benchmark::State& state) {
  std::vector<uint8_t> bytes(256);
  int64_t seq = 0;
  for (auto _ : state) {
    aula::lockstep_ack_t ack = ackAt(++seq);
    bytes.resize(static_cast<size_t>(ack.getEncodedSize()));
    ack.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    benchmark::DoNotOptimize(bytes.data());
  }
}
BENCHMARK(BM_AckUnsigned);

// Signed by the component, checked by the simulator (each side's Signer made once, as in a run).
void BM_AckSignedAndChecked(benchmark::State& state) {
  const aula::auth::Key client_key = aula::auth::clientKey(aula::auth::randomKey(), "vacuum-cleaner");
  aula::auth::Signer component(client_key), simulator(client_key);
  std::vector<uint8_t> bytes(256);
  int64_t seq = 0;
  for (auto _ : state) {
    aula::lockstep_ack_t ack = ackAt(++seq);
    aula::auth::sign(component, kChannel, ack);
    bytes.resize(static_cast<size_t>(ack.getEncodedSize()));
    ack.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    benchmark::DoNotOptimize(aula::auth::verify(simulator, kChannel, ack));
  }
}
BENCHMARK(BM_AckSignedAndChecked);

}  // namespace

BENCHMARK_MAIN();
