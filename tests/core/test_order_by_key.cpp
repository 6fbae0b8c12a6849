// OrderByDistinctKeys against an argsort by std::sort: distinct keys with gaps below the limit, in
// random order, from none to a million (the slot table then on huge pages).
#include "order_by_key.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

using namespace tessera;

namespace
{
/// count distinct keys from [0, limit), in random order.
std::vector<std::int32_t> DistinctKeys(std::size_t count, std::size_t limit, std::uint64_t seed)
{
  std::vector<std::int32_t> all(limit);
  std::iota(all.begin(), all.end(), 0);
  std::mt19937_64 random(seed);
  std::shuffle(all.begin(), all.end(), random);
  all.resize(count);
  return all;
}

std::vector<std::int32_t> ArgsortBySort(const std::vector<std::int32_t>& keys)
{
  std::vector<std::int32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(
    order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return keys[a] < keys[b]; });
  return order;
}
} // namespace

TEST(OrderByKey, MatchesAnArgsortBySorting)
{
  const std::size_t cases[][2] = { { 0, 0 },
    { 0, 10 },
    { 1, 1 },
    { 7, 7 },
    { 100, 1000 },
    { 1000, 1001 },
    { std::size_t(1) << 20, (std::size_t(3) << 20) / 2 } };
  std::uint64_t seed = 1;
  for (const auto& c : cases)
  {
    const std::vector<std::int32_t> keys = DistinctKeys(c[0], c[1], seed++);
    const std::vector<std::int32_t> order = OrderByDistinctKeys(keys.data(), keys.size(), c[1]);
    EXPECT_EQ(order, ArgsortBySort(keys)) << c[0] << " keys below " << c[1];
  }
}

TEST(OrderByKey, KeysAlreadyInOrderKeepTheirPositions)
{
  const std::vector<std::int32_t> keys{ 0, 2, 3, 9 };
  EXPECT_EQ(
    OrderByDistinctKeys(keys.data(), keys.size(), 10), (std::vector<std::int32_t>{ 0, 1, 2, 3 }));
  const std::vector<std::int32_t> reversed{ 9, 3, 2, 0 };
  EXPECT_EQ(OrderByDistinctKeys(reversed.data(), reversed.size(), 10),
    (std::vector<std::int32_t>{ 3, 2, 1, 0 }));
}
