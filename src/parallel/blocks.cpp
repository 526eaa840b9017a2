#include "src/parallel/blocks.hpp"

#include <algorithm>

namespace whirl::parallel {

std::vector<Block> contiguousBlocks(int n, int parts) {
  std::vector<Block> blocks;
  if (n <= 0) return blocks;
  const int b = std::clamp(parts, 1, n);
  const int base = n / b, larger = n % b;
  int begin = 0;
  for (int i = 0; i < b; ++i) {
    const int end = begin + base + (i < larger ? 1 : 0);
    blocks.push_back({begin, end});
    begin = end;
  }
  return blocks;
}

}  // namespace whirl::parallel
