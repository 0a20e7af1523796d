#include "runtime/evo/map_elites/grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace esc::evo::qd {

Grid::Grid(std::vector<std::size_t> bins) : bins_(std::move(bins)) {
  if (bins_.empty() || bins_.size() > 3) throw std::invalid_argument("bins: a grid has one to three descriptors");
  for (const std::size_t b : bins_) {
    if (b == 0) throw std::invalid_argument("bins: every descriptor needs at least one bin");
    if (b > kMaxGridCells / cells_) throw std::invalid_argument("bins: more than 10^8 cells");
    cells_ *= b;
  }
}

std::size_t Grid::cell_of(std::span<const double> unit) const {
  std::size_t cell = 0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    const double scaled = std::floor(unit[i] * static_cast<double>(bins_[i]));
    const auto bin = std::min(static_cast<std::size_t>(std::max(scaled, 0.0)), bins_[i] - 1);
    cell = cell * bins_[i] + bin;
  }
  return cell;
}

}  // namespace esc::evo::qd
