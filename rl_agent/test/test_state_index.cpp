#include "rl_agent/planner/state_index.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

#include "rl_agent/planner/state_hash.h"
#include "rl_common/random.h"

namespace {

using rl_agent::StateHash;
using rl_agent::StateIndex;

TEST(StateIndex, MatchesAMapUnderRandomInsertsAndErasesWithCollidingHashes) {
  // Slots stand for keys; slot k's hash is ~(k % 7): seven home positions at the end of the
  // array (many collisions, probe runs that wrap around to its start), so backward-shift
  // deletion must keep every run reachable.
  StateIndex index;
  std::set<std::uint32_t> present;
  rl_common::Random rng(5);
  auto hashOf = [](std::uint32_t k) { return ~static_cast<std::uint64_t>(k % 7); };
  for (int op = 0; op < 20000; ++op) {
    const auto k = static_cast<std::uint32_t>(rng.uniformInt(0, 299));
    const bool has = present.count(k) > 0;
    const std::uint32_t found = index.find(hashOf(k), [&](std::uint32_t s) { return s == k; });
    ASSERT_EQ(found, has ? k : StateIndex::kNone) << "op " << op;
    if (has && rng.uniformInt(0, 1) == 0) {
      ASSERT_TRUE(index.erase(hashOf(k), k));
      present.erase(k);
    } else if (!has) {
      index.insert(hashOf(k), k);
      present.insert(k);
    }
    ASSERT_EQ(index.size(), present.size());
  }
  for (std::uint32_t k = 0; k < 300; ++k) {
    const std::uint32_t found = index.find(hashOf(k), [&](std::uint32_t s) { return s == k; });
    EXPECT_EQ(found, present.count(k) ? k : StateIndex::kNone);
  }
  EXPECT_FALSE(index.erase(hashOf(1000), 1000));
}

TEST(StateIndex, EmptyIndexFindsNothing) {
  const StateIndex index;
  EXPECT_EQ(index.find(42, [](std::uint32_t) { return true; }), StateIndex::kNone);
  EXPECT_EQ(index.size(), 0u);
}

TEST(StateHash, EqualStatesHashAlikeAndOneBitChangesIt) {
  const StateHash h;
  EXPECT_EQ(h({0.0f, 1.0f, 2.0f}), h({-0.0f, 1.0f, 2.0f}));
  EXPECT_EQ(h({1.0f, -0.0f}), h({1.0f, 0.0f}));
  // Odd and even lengths, a feature's position and the length all count.
  std::set<std::size_t> seen;
  const std::vector<std::vector<float>> states{{},
                                               {0.0f},
                                               {0.0f, 0.0f},
                                               {1.0f},
                                               {1.0f, 0.0f},
                                               {0.0f, 1.0f},
                                               {0.0f, 0.0f, 1.0f},
                                               {1.0f, 2.0f, 3.0f},
                                               {3.0f, 2.0f, 1.0f},
                                               {1.0f, 2.0f, 3.0f, 4.0f}};
  for (const auto& s : states) seen.insert(h(s));
  EXPECT_EQ(seen.size(), states.size());
  // A 17-feature grid state: every single-unit change of any feature gives a new hash.
  std::vector<float> s(17, 3.0f);
  const std::size_t base = h(s);
  for (std::size_t j = 0; j < s.size(); ++j) {
    auto t = s;
    t[j] += 1.0f;
    EXPECT_NE(h(t), base) << "feature " << j;
  }
}

}  // namespace
