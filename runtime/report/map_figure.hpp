#pragma once
// A map of a plane of two descriptors, as the report and `esc replay --evaluations` draw it:
// rectangles in unit coordinates over the descriptors' declared ranges, each coloured by its
// value (viridis) with a colour bar, and outlines drawn over them (an arena's walls).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "runtime/evo/optimizer.hpp"

namespace esc::report {

// Viridis at t in [0, 1] (matplotlib's, at 9 stops, interpolated linearly), as #rrggbb.
[[nodiscard]] std::string viridis(double t);

struct Tile {
  double x0, y0, x1, y1;   // unit coordinates: 0 is a range's lower end, 1 its upper
  double value;            // NaN: empty (grey)
};

using UnitPoint = std::array<double, 2>;

struct MapFigure {
  std::string title, x_title, y_title, value_title, note;
  evo::Bounds x_range, y_range;
  std::vector<Tile> tiles;
  // Values are log10 of counts: the colour bar's ends are labelled with the counts.
  bool log_counts = false;
  // Closed polygons in unit coordinates, filled dark over the tiles (walls, obstacles), and
  // the outline of a rectangle (an arena's border), and a point to mark (a goal).
  std::vector<std::vector<UnitPoint>> solids{};
  std::optional<std::array<UnitPoint, 2>> border{};
  std::optional<UnitPoint> mark{};
};

[[nodiscard]] std::string render_map(const MapFigure& m);

}  // namespace esc::report
