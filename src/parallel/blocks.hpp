#pragma once
/// \file
/// Contiguous blocks of a list, for work that is a chain (each item starts from its predecessor's
/// result, as the trim schedule's wind speeds do) and so cannot be dealt out item by item.
#include <vector>

namespace whirl::parallel {

/// Items [begin, end) of a list.
struct Block {
  int begin = 0;
  int end = 0;
};

/// Items 0 … n−1 cut into min(parts, n) contiguous blocks, in order, none empty, their sizes
/// differing by one at most (the larger ones first); none for n = 0. parts < 1 counts as 1.
std::vector<Block> contiguousBlocks(int n, int parts);

}  // namespace whirl::parallel
