#include "runtime/report/evaluation_map.hpp"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "runtime/report/map_figure.hpp"

namespace esc::report {

namespace {

// The corners of a box (rotated about its centre), in unit coordinates.
std::vector<UnitPoint> corners(const sim::BoxObstacle& b, const auto& unit) {
  const double c = std::cos(b.angle_rad), s = std::sin(b.angle_rad);
  std::vector<UnitPoint> out;
  for (const auto& [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    const double dx = u * b.size_m.x / 2, dy = v * b.size_m.y / 2;
    out.push_back(unit(b.center_m.x + c * dx - s * dy, b.center_m.y + s * dx + c * dy));
  }
  return out;
}

// The arena's walls, obstacles and goal over `m`'s ranges.
void draw_arena(MapFigure& m, const sim::ArenaSpec& a) {
  const auto unit = [&](double x, double y) {
    return UnitPoint{(x - m.x_range.lower) / (m.x_range.upper - m.x_range.lower),
                     (y - m.y_range.lower) / (m.y_range.upper - m.y_range.lower)};
  };
  m.border = {unit(0, 0), unit(a.width_m, a.height_m)};
  for (const sim::BoxObstacle& b : a.boxes) m.solids.push_back(corners(b, unit));
  for (const sim::WallSegment& w : a.walls) m.solids.push_back(corners(sim::wall_box(w), unit));
  for (const sim::CylinderObstacle& c : a.cylinders) {
    std::vector<UnitPoint> round;
    constexpr int kSides = 32;
    for (int i = 0; i < kSides; ++i) {
      const double t = 2.0 * std::numbers::pi * i / kSides;
      round.push_back(unit(c.center_m.x + c.radius_m * std::cos(t), c.center_m.y + c.radius_m * std::sin(t)));
    }
    m.solids.push_back(std::move(round));
  }
  if (a.goal) m.mark = unit(a.goal->x, a.goal->y);
}

}  // namespace

std::string evaluation_map_svg(const EvaluationMap& e) {
  MapFigure m;
  m.title = e.title;
  m.x_title = e.x_title;
  m.y_title = e.y_title;
  m.x_range = e.x_range;
  m.y_range = e.y_range;
  m.value_title = "evaluations in a square";
  m.log_counts = true;
  const std::size_t n = e.squares;
  std::vector<std::size_t> count(n * n, 0);
  std::size_t outside = 0;
  const auto square = [n](double v, const evo::Bounds& r) {
    const double u = (v - r.lower) / (r.upper - r.lower);
    // The upper end of a range belongs to the last square.
    return u >= 0.0 && u <= 1.0 ? std::min(static_cast<std::size_t>(u * static_cast<double>(n)), n - 1) : n;
  };
  for (std::size_t k = 0; k < e.x.size() && k < e.y.size(); ++k) {
    const std::size_t i = square(e.x[k], e.x_range), j = square(e.y[k], e.y_range);
    if (i < n && j < n) ++count[i * n + j];
    else ++outside;
  }
  const double d = 1.0 / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (count[i * n + j] > 0)
        m.tiles.push_back({static_cast<double>(i) * d, static_cast<double>(j) * d, static_cast<double>(i + 1) * d,
                           static_cast<double>(j + 1) * d, std::log10(static_cast<double>(count[i * n + j]))});
  m.note = fmt::format("{} evaluations in squares of 1/{} of each range (log colour scale); grey: none{}", e.x.size(),
                       n, outside > 0 ? fmt::format("; {} outside the declared ranges, not drawn", outside) : "");
  if (e.arena != nullptr) draw_arena(m, *e.arena);
  return render_map(m);
}

}  // namespace esc::report
