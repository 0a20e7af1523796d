#include "runtime/sim/neighbours.hpp"

#include <cmath>
#include <limits>

#include "runtime/sim/geometry2d.hpp"

namespace esc::sim {

namespace {

constexpr double kNoHit = std::numeric_limits<double>::infinity();
// The grid's cells at most: a reach smaller than an arena's 1/64th gains nothing finer.
constexpr int kMaxCellsPerSide = 64;

// Cells of at least `cell_m`, and no more cells than robots: building the grid (clearing and
// summing every cell's count) then costs what the robots do, however large the arena.
double cell_size(std::size_t robots, double width_m, double height_m, double cell_m) {
  const double per_robot = std::sqrt(width_m * height_m / static_cast<double>(std::max<std::size_t>(robots, 1)));
  return std::max({cell_m, per_robot, width_m / kMaxCellsPerSide, height_m / kMaxCellsPerSide});
}

// A convex polygon (counter-clockwise) clipped against the ray, edge by edge (Cyrus-Beck).
double ray_polygon_hit(std::span<const Vec2> ccw, Vec2 o, double dx, double dy) noexcept {
  double enter = 0.0;
  double leave = kNoHit;
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 a = ccw[i];
    const Vec2 b = ccw[(i + 1) % ccw.size()];
    // Outward normal of a counter-clockwise edge, unnormalised; `side` > 0: the origin is outside it.
    const double nx = b.y - a.y;
    const double ny = a.x - b.x;
    const double side = nx * (o.x - a.x) + ny * (o.y - a.y);
    const double toward = nx * dx + ny * dy;
    if (toward == 0.0) {
      if (side > 0.0) return kNoHit;   // parallel to the edge, outside it
      continue;
    }
    const double at = -side / toward;
    if (toward < 0.0) enter = std::max(enter, at);
    else leave = std::min(leave, at);
    if (enter > leave) return kNoHit;
  }
  return enter;
}

}  // namespace

double ray_body_hit(const PlacedBody& body, Vec2 origin, double dx, double dy) noexcept {
  const double r2 = body.radius_m * body.radius_m;
  const double circle = ray_circle_hit(body.centre.x, body.centre.y, r2, origin.x, origin.y, dx, dy);
  if (body.outline.empty() || circle == kNoHit) return circle;
  return ray_polygon_hit(body.outline, origin, dx, dy);
}

void cast_fan_at_bodies(std::span<const PlacedBody> bodies, Vec2 origin, int n, const double* dx, const double* dy,
                        double* t) noexcept {
  for (const PlacedBody& b : bodies) {
    const double ex = b.centre.x - origin.x;
    const double ey = b.centre.y - origin.y;
    double far = 0.0;
    for (int i = 0; i < n; ++i) far = std::max(far, t[i]);
    const double reach = far + b.radius_m;
    if (ex * ex + ey * ey > reach * reach) continue;
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], ray_body_hit(b, origin, dx[i], dy[i]));
  }
}

Neighbours::Neighbours(std::size_t robots, double width_m, double height_m, double cell_m)
    : cell_m_(cell_size(robots, width_m, height_m, cell_m)),
      columns_(std::max(1, static_cast<int>(std::ceil(width_m / cell_m_)))),
      rows_(std::max(1, static_cast<int>(std::ceil(height_m / cell_m_)))),
      start_(static_cast<std::size_t>(columns_ * rows_) + 1, 0),
      items_(robots),
      cell_of_(robots) {}

void Neighbours::build(std::span<const Vec2> centres) noexcept {
  // A counting sort by cell: robots stay in index order within their cell.
  std::fill(start_.begin(), start_.end(), 0);
  for (std::size_t j = 0; j < centres.size(); ++j) {
    cell_of_[j] = static_cast<std::uint32_t>(row(centres[j].y) * columns_ + column(centres[j].x));
    ++start_[cell_of_[j] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  for (std::size_t j = 0; j < centres.size(); ++j) items_[start_[cell_of_[j]]++] = static_cast<std::uint32_t>(j);
  // start_[c] now holds where cell c + 1 begins: shift back.
  for (std::size_t c = start_.size() - 1; c > 0; --c) start_[c] = start_[c - 1];
  start_[0] = 0;
}

}  // namespace esc::sim
