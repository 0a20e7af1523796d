#pragma once
// Where a run's evaluations fall over two descriptors (`esc replay --evaluations`): the
// plane of their declared ranges cut into squares, each coloured by how many evaluations
// fell in it (log scale: a run's 250,000 crowd a few squares). When the two descriptors are
// the robot's final x and y, the arena is drawn over the squares: Lehman & Stanley's
// picture of where every robot of a method ends in the maze (2011, figure 4).
#include <cstddef>
#include <span>
#include <string>

#include "runtime/evo/optimizer.hpp"
#include "runtime/sim/arena.hpp"

namespace esc::report {

struct EvaluationMap {
  std::string title;
  std::string x_title, y_title;
  evo::Bounds x_range, y_range;      // the descriptors' declared ranges
  std::span<const double> x, y;      // one value of each descriptor per evaluation
  std::size_t squares = 120;         // per side
  // Null, or the arena whose x and y (metres) the two descriptors measure: drawn over them.
  const sim::ArenaSpec* arena = nullptr;
};

[[nodiscard]] std::string evaluation_map_svg(const EvaluationMap& map);

}  // namespace esc::report
