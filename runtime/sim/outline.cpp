#include "runtime/sim/outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

namespace esc::sim {

double twice_signed_area(std::span<const Vec2> outline) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) sum += cross(outline[i], outline[(i + 1) % outline.size()]);
  return sum;
}

std::vector<Vec2> counter_clockwise(std::span<const Vec2> outline) {
  std::vector<Vec2> out(outline.begin(), outline.end());
  if (twice_signed_area(outline) < 0.0) std::reverse(out.begin(), out.end());
  return out;
}

double smallest_turn(std::span<const Vec2> outline, int& at) noexcept {
  const std::size_t n = outline.size();
  const double direction = twice_signed_area(outline) < 0.0 ? -1.0 : 1.0;
  double least = std::numeric_limits<double>::infinity();
  double turned = 0.0;   // radians, in the outline's direction
  at = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 in = minus(outline[i], outline[(i + n - 1) % n]);
    const Vec2 out = minus(outline[(i + 1) % n], outline[i]);
    const double lengths = std::hypot(in.x, in.y) * std::hypot(out.x, out.y);
    // A repeated vertex has no turn: 0, refused as a convex outline's turns are positive.
    const double turn = lengths > 0.0 ? direction * cross(in, out) / lengths : 0.0;
    turned += std::atan2(direction * cross(in, out), in.x * out.x + in.y * out.y);
    // Turning the same way at every vertex but round more than once (a star): no turn here
    // makes it convex.
    const bool wound = turned > 2 * std::numbers::pi + 1e-9;
    if (wound || !(turn >= least)) {
      least = wound ? 0.0 : turn;
      at = static_cast<int>(i);
    }
    if (wound) break;
  }
  return least;
}

double origin_depth(std::span<const Vec2> ccw, Vec2 p) noexcept {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 a = ccw[i];
    const Vec2 e = minus(ccw[(i + 1) % ccw.size()], a);
    // The point's distance to the left of edge a -> a + e.
    least = std::min(least, cross(e, minus(p, a)) / std::hypot(e.x, e.y));
  }
  return least;
}

double smallest_corner(std::span<const Vec2> ccw, int& at) noexcept {
  const std::size_t n = ccw.size();
  double least = std::numbers::pi;
  at = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 back = minus(ccw[(i + n - 1) % n], ccw[i]);
    const Vec2 ahead = minus(ccw[(i + 1) % n], ccw[i]);
    const double corner = std::atan2(std::abs(cross(ahead, back)), ahead.x * back.x + ahead.y * back.y);
    if (corner < least) {
      least = corner;
      at = static_cast<int>(i);
    }
  }
  return least;
}

std::vector<Vec2> inset(std::span<const Vec2> ccw, double margin) {
  const std::size_t n = ccw.size();
  std::vector<Vec2> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Vertex i moved where the two edges meeting there, each shifted inwards by the margin,
    // cross: along the bisector, margin / cos(half the turn) from the vertex.
    const Vec2 in = minus(ccw[i], ccw[(i + n - 1) % n]);
    const Vec2 out_edge = minus(ccw[(i + 1) % n], ccw[i]);
    const double li = std::hypot(in.x, in.y), lo = std::hypot(out_edge.x, out_edge.y);
    const Vec2 ni{-in.y / li, in.x / li};          // inward normals (left of each edge)
    const Vec2 no{-out_edge.y / lo, out_edge.x / lo};
    const double k = margin / (1.0 + ni.x * no.x + ni.y * no.y);
    out[i] = {ccw[i].x + k * (ni.x + no.x), ccw[i].y + k * (ni.y + no.y)};
  }
  return out;
}

double polar_gyration_sq(std::span<const Vec2> ccw) noexcept {
  // Over the fan of triangles (origin, a, b): area c / 2 and polar moment
  // c (a.a + a.b + b.b) / 12, with c = a x b.
  double area2 = 0.0, moment12 = 0.0;
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 a = ccw[i];
    const Vec2 b = ccw[(i + 1) % ccw.size()];
    const double c = cross(a, b);
    area2 += c;
    moment12 += c * (a.x * a.x + a.y * a.y + a.x * b.x + a.y * b.y + b.x * b.x + b.y * b.y);
  }
  return (moment12 / 12.0) / (area2 / 2.0);
}

void place_points(std::span<const Vec2> outline, const Pose& pose, std::span<Vec2> out) noexcept {
  const double c = std::cos(pose.heading_rad), s = std::sin(pose.heading_rad);
  for (std::size_t i = 0; i < outline.size(); ++i)
    out[i] = {pose.x_m + c * outline[i].x - s * outline[i].y, pose.y_m + s * outline[i].x + c * outline[i].y};
}

}  // namespace esc::sim
