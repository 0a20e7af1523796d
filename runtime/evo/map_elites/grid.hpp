#pragma once
// MAP-Elites' cells as Mouret & Clune (2015) define them: each descriptor's range cut into
// equal bins, a cell per combination. A descriptor in unit coordinates (DescriptorSpace)
// falls in bin floor(u * bins) of its dimension, the upper bound itself in the last bin, a
// value outside the range (clamped to it) in the edge bin. Cells are numbered in row-major
// order, the first descriptor varying slowest (numpy's ravel_multi_index, as pyribs does).
#include <cstddef>
#include <span>
#include <vector>

namespace esc::evo::qd {

// Cells a grid may have: 10^8, a few GiB of elites at the smallest genome; beyond that the
// bins are far finer than any evaluation budget fills.
inline constexpr std::size_t kMaxGridCells = 100'000'000;

class Grid {
 public:
  // One to three descriptors, each cut into at least one bin. Throws std::invalid_argument
  // ("bins: ...") otherwise or beyond kMaxGridCells.
  explicit Grid(std::vector<std::size_t> bins);

  [[nodiscard]] std::size_t cells() const noexcept { return cells_; }
  [[nodiscard]] std::size_t dims() const noexcept { return bins_.size(); }
  [[nodiscard]] const std::vector<std::size_t>& bins() const noexcept { return bins_; }
  // The cell of a descriptor in unit coordinates (each in [0, 1]).
  [[nodiscard]] std::size_t cell_of(std::span<const double> unit) const;

  friend bool operator==(const Grid&, const Grid&) = default;

 private:
  std::vector<std::size_t> bins_;
  std::size_t cells_ = 1;
};

}  // namespace esc::evo::qd
