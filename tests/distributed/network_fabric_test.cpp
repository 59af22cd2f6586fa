// The alpha-beta network model: the presets' published figures, the cost of a message, of a
// batched forward and of a collective written out by hand, flag errors, and the modelled time of
// a small hand-made run.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "distributed/network_fabric.h"
#include "util/error.h"

namespace proxyvis {
namespace {

TEST(NetworkFabric, PresetsCarryThePublishedFigures) {
  const NetworkFabric ib = networkFabric("ib-hdr", -1, -1);
  EXPECT_EQ(ib.alpha_us, 1.6);
  EXPECT_EQ(ib.beta_gbps, 23);
  EXPECT_EQ(networkFabric("roce", -1, -1).alpha_us, 3.5);
  EXPECT_EQ(networkFabric("roce", -1, -1).beta_gbps, 11);
  EXPECT_EQ(networkFabric("10gbe-tcp", -1, -1).alpha_us, 20);
  EXPECT_EQ(networkFabric("10gbe-tcp", -1, -1).beta_gbps, 1.1);
  const NetworkFabric flat = networkFabric("unbatched-20us", -1, -1);
  EXPECT_TRUE(flat.upper_bound);
  EXPECT_EQ(flat.per_item_us, 20);
  const NetworkFabric shm = networkFabric("shm", -1, -1);
  EXPECT_TRUE(shm.measured);
  EXPECT_EQ(withMeasured(shm, 0.5, 8).alpha_us, 0.5);
  EXPECT_EQ(withMeasured(ib, 0.5, 8).alpha_us, 1.6);  // only shm takes the measured figures
}

TEST(NetworkFabric, MessageAndBatchedForwardCosts) {
  const NetworkFabric ib = networkFabric("ib-hdr", -1, -1);
  // 100 requests of 32 bytes: 1.6 us + 3200 B / 23 GB/s.
  EXPECT_NEAR(ib.messageSeconds(3200, 100), 1.6e-6 + 3200.0 / 23e9, 1e-15);
  // A batched forward at n = 100 per message: a request and an answer message shared by 100,
  // 33 bytes each: 2 alpha / n + 33 B / beta = 0.032 us + 0.0014 us.
  const double per_forward = ib.sendSeconds(2, 3300, 100) / 100;
  EXPECT_NEAR(per_forward, 2 * 1.6e-6 / 100 + 33.0 / 23e9, 1e-15);
  EXPECT_LT(per_forward, 0.04e-6);
  // The flat upper bound charges per forwarded segment, whatever the batching.
  const NetworkFabric flat = networkFabric("unbatched-20us", -1, -1);
  EXPECT_NEAR(flat.sendSeconds(2, 3300, 100), 100 * 20e-6, 1e-12);
  // The 10 GbE forward costs about 0.4 us at n = 100.
  const NetworkFabric tcp = networkFabric("10gbe-tcp", -1, -1);
  EXPECT_NEAR(tcp.sendSeconds(2, 3300, 100) / 100, 0.4e-6 + 33.0 / 1.1e9, 1e-15);
}

TEST(NetworkFabric, CollectivesTakeLog2Steps) {
  const NetworkFabric ib = networkFabric("ib-hdr", -1, -1);
  EXPECT_EQ(ib.collectiveSeconds(1), 0);
  EXPECT_NEAR(ib.collectiveSeconds(2), 1.6e-6, 1e-15);
  EXPECT_NEAR(ib.collectiveSeconds(3), 2 * 1.6e-6, 1e-15);
  EXPECT_NEAR(ib.collectiveSeconds(4), 2 * 1.6e-6, 1e-15);
  EXPECT_NEAR(ib.collectiveSeconds(1000), 10 * 1.6e-6, 1e-15);
  EXPECT_NEAR(ib.reductionSeconds(4, 23000), 2 * (1.6e-6 + 1e-6), 1e-15);
}

TEST(NetworkFabric, CustomFiguresAndErrors) {
  const NetworkFabric custom = networkFabric("ib-hdr", 100, -1);
  EXPECT_EQ(custom.name, "custom");
  EXPECT_EQ(custom.alpha_us, 100);
  EXPECT_EQ(custom.beta_gbps, 23);
  EXPECT_EQ(networkFabric("shm", 2, 5).beta_gbps, 5);
  EXPECT_FALSE(networkFabric("shm", 2, 5).measured);
  auto fails = [](const std::string& name, double a, double b) {
    try {
      networkFabric(name, a, b);
    } catch (const Error& e) {
      return e.exitCode() == kExitBadInput;
    }
    return false;
  };
  EXPECT_TRUE(fails("infiniband", -1, -1));
  EXPECT_TRUE(fails("ib-hdr", std::nan(""), -1));
  EXPECT_TRUE(fails("ib-hdr", -1, 0));
  EXPECT_TRUE(fails("ib-hdr", -1, std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(fails("unbatched-20us", 1, -1));
  EXPECT_TRUE(fails("shm", 2, -1));  // shared memory's bandwidth is unknown until measured
}

TEST(NetworkFabric, ModelledTimeSumsTheSlowestRankPerRoundAndPhase) {
  NetworkFabric f;
  f.name = "test";
  f.alpha_us = 10;
  f.beta_gbps = 1;  // 1 byte per ns
  // Two ranks, two rounds (loads[rank][round] = {request phase, answer phase}).
  // Round 1, requests: rank 0 computes 1 ms and sends 2 messages of 1000 bytes in all (1 + 0.02 +
  // 0.001 ms), rank 1 computes 1.5 ms and sends nothing: rank 1 is the slowest (1.5 ms).
  // Round 1, answers: rank 1 answers in 0.4 ms with 2 messages of 10 bytes (0.4 + 0.02 + 0.00001
  // ms), rank 0 answers nothing: 0.42001 ms.
  // Round 2, requests: rank 0 computes 0.1 ms and sends one message of 10^6 bytes (10 us + 1 ms),
  // rank 1 computes 0.2 ms: rank 0 is the slowest. No answers.
  std::vector<std::vector<RoundLoad>> loads = {
      {{{1e-3, 2, 1000, 10}, {}}, {{0.1e-3, 1, 1000000, 1}, {}}},
      {{{1.5e-3, 0, 0, 0}, {0.4e-3, 2, 10, 0}}, {{0.2e-3, 0, 0, 0}, {}}}};
  const ModelledTime t = modelTime(f, loads, 0.3e-3, 5e-6);
  const double round1 = 1.5e-3 + (0.4e-3 + 20e-6 + 10e-9);
  const double round2 = 0.1e-3 + 10e-6 + 1e-3;
  const double control = 2 * 10e-6;
  EXPECT_NEAR(t.seconds, round1 + round2 + control + 0.3e-3 + 5e-6, 1e-12);
  EXPECT_NEAR(t.compute_seconds, 1.5e-3 + 0.4e-3 + 0.2e-3 + 0.3e-3, 1e-12);
  EXPECT_NEAR(t.message_seconds, (20e-6 + 1e-6) + (20e-6 + 10e-9) + (10e-6 + 1e-3), 1e-12);
  EXPECT_NEAR(t.control_seconds, control + 5e-6, 1e-12);
  EXPECT_EQ(t.rounds, 2u);
}

TEST(NetworkFabric, ModelledTimesSumAndAverageOverRuns) {
  ModelledTime sum;
  sum += ModelledTime{1.0, 0.5, 0.25, 0.125, 4};
  sum += ModelledTime{3.0, 1.5, 0.75, 0.375, 6};
  const ModelledTime mean = sum.meanOver(2);
  EXPECT_EQ(mean.seconds, 2.0);
  EXPECT_EQ(mean.compute_seconds, 1.0);
  EXPECT_EQ(mean.message_seconds, 0.5);
  EXPECT_EQ(mean.control_seconds, 0.25);
  EXPECT_EQ(mean.rounds, 5u);
}

}  // namespace
}  // namespace proxyvis
