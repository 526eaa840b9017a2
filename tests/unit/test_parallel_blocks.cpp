// The contiguous blocks of a chained list (src/parallel/blocks.hpp) by which the trim schedule spreads
// its wind speeds over the ranks, and the results of parallelMapBytes on every rank (in one process).
#include <gtest/gtest.h>

#include <algorithm>

#include "src/parallel/blocks.hpp"
#include "src/parallel/parallel_map.hpp"

namespace whirl {
namespace {

TEST(ParallelBlocks, CoverEveryItemInOrderNoneEmpty) {
  for (int n = 0; n <= 30; ++n)
    for (int parts = -1; parts <= 9; ++parts) {
      const std::vector<parallel::Block> b = parallel::contiguousBlocks(n, parts);
      const int expected = n == 0 ? 0 : std::min(std::max(parts, 1), n);
      ASSERT_EQ(static_cast<int>(b.size()), expected) << n << " items, " << parts << " parts";
      int next = 0, smallest = n, largest = 0;
      for (const parallel::Block& k : b) {
        EXPECT_EQ(k.begin, next) << n << " items, " << parts << " parts";  // contiguous, in order
        EXPECT_GT(k.end, k.begin);                                         // none empty
        if (k.end - k.begin > smallest) ADD_FAILURE() << "a larger block after a smaller one";
        smallest = std::min(smallest, k.end - k.begin);
        largest = std::max(largest, k.end - k.begin);
        next = k.end;
      }
      EXPECT_EQ(next, n);  // every item
      if (!b.empty()) {
        EXPECT_LE(largest - smallest, 1);
      }
    }
}

TEST(ParallelBlocks, ExampleSplit) {
  // 11 wind speeds (4:2:24) on 2 ranks: 4…14 m/s, then 16…24 m/s.
  const std::vector<parallel::Block> b = parallel::contiguousBlocks(11, 2);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].begin, 0);
  EXPECT_EQ(b[0].end, 6);
  EXPECT_EQ(b[1].begin, 6);
  EXPECT_EQ(b[1].end, 11);
}

TEST(ParallelBlocks, OneProcessIsOneRankAndEveryRankGetsTheResults) {
  EXPECT_EQ(parallel::mapSize(), 1);  // not under mpirun: the serial schedule, one chain
  parallel::MapOptions opt;
  opt.every_rank = true;
  const std::vector<std::string> out = parallel::parallelMapBytes(
      4, [](int k) { return std::string(static_cast<size_t>(k), 'x'); }, opt);
  ASSERT_EQ(out.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(out[static_cast<size_t>(k)], std::string(static_cast<size_t>(k), 'x'));
}

}  // namespace
}  // namespace whirl
