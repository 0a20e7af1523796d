#pragma once
// What one run's optimizer holds at the height of a generation, so that the campaign refuses
// a size that cannot fit before it writes anything, and says what to lower. Each algorithm
// counts its own (in its folder, reached through the registry): the genomes it holds and
// hands out, what it ranks them with (a sort, an archive's tree, restarts' larger
// populations). Counted as the heap holds them, a small vector's header and allocation
// overhead included: with 18 weights a genome's 144 bytes take 200, and at a million
// members that difference is what a check missed. In doubles: sizes multiply beyond any
// integer type.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace esc::evo {

struct MemoryPeak {
  double bytes = 0.0;
  double candidates = 0.0;   // the most one generation asks for (IPOP's doubled population)
  std::string what;      // the part that dominates it: "the non-dominated sort of 2,000,000 members"
  std::string setting;   // the `--set` key that sizes that part: "nsga2.population"
};

// Bytes one allocation of `bytes` takes on the heap (glibc: an 8-byte header, rounded up to
// 16, 32 at least); 0 for none.
[[nodiscard]] inline double heap_bytes(double bytes) {
  if (bytes <= 0.0) return 0.0;
  return std::max(32.0, std::ceil((bytes + 8.0) / 16.0) * 16.0);
}

// `count` vectors of `length` doubles each held in a vector: their headers and allocations.
[[nodiscard]] inline double rows_bytes(double count, double length) {
  return count * (sizeof(std::vector<double>) + heap_bytes(length * sizeof(double)));
}

// What a StateWriter (state_bytes.hpp) that grew to `bytes` holds: its vector doubles from
// 64 bytes.
[[nodiscard]] inline double writer_bytes(double bytes) {
  return bytes <= 64.0 ? 64.0 : 64.0 * std::exp2(std::ceil(std::log2(bytes / 64.0)));
}

}  // namespace esc::evo
