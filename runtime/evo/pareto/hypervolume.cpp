#include "runtime/evo/pareto/hypervolume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace esc::evo {

namespace {

using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;

// A non-negative quantity held finite: the largest double where it overflowed.
double held(double v) { return std::min(v, std::numeric_limits<double>::max()); }

// The area dominated by `sorted` (ascending, lexicographically) within the reference
// (r0, r1); every point lies strictly below it.
double area(const std::vector<Point2>& sorted, double r0, double r1) {
  double total = 0.0;
  double best = r1;  // the lowest second coordinate so far
  for (const Point2& p : sorted) {
    if (p[1] >= best) continue;
    total = held(total + held(held(r0 - p[0]) * held(best - p[1])));
    best = p[1];
  }
  return total;
}

double volume(std::vector<Point3> points, std::span<const double> r) {
  std::sort(points.begin(), points.end(), [](const Point3& a, const Point3& b) {
    return std::array{a[2], a[0], a[1]} < std::array{b[2], b[0], b[1]};
  });
  // Slice k lies between the third objectives of points k and k + 1 (the reference after
  // the last); the points up to k dominate the same 2-D region throughout it.
  std::vector<Point2> below;
  double total = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point2 p{points[k][0], points[k][1]};
    below.insert(std::upper_bound(below.begin(), below.end(), p), p);
    const double next = k + 1 < points.size() ? points[k + 1][2] : r[2];
    if (next > points[k][2]) total = held(total + held(area(below, r[0], r[1]) * held(next - points[k][2])));
  }
  return total;
}

}  // namespace

double hypervolume(const ObjectiveRows& points, std::span<const double> reference) {
  const std::size_t m = reference.size();
  if (m != 2 && m != 3)
    throw std::invalid_argument("hypervolume: 2 or 3 objectives, the reference has " + std::to_string(m));
  for (const double r : reference)
    if (!std::isfinite(r)) throw std::invalid_argument("hypervolume: the reference point must be finite");

  std::vector<Point3> inside;  // the third coordinate unused with two objectives
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<double>& p = points[i];
    if (p.size() != m)
      throw std::invalid_argument("hypervolume: point " + std::to_string(i) + " has " + std::to_string(p.size()) +
                                  " objectives, the reference " + std::to_string(m));
    bool below = true;
    for (std::size_t k = 0; k < m; ++k) below = below && p[k] < reference[k];  // false for NaN
    if (below) inside.push_back({p[0], p[1], m == 3 ? p[2] : 0.0});
  }
  if (m == 3) return volume(std::move(inside), reference);
  std::vector<Point2> flat;
  for (const Point3& p : inside) flat.push_back({p[0], p[1]});
  std::sort(flat.begin(), flat.end());
  return area(flat, reference[0], reference[1]);
}

}  // namespace esc::evo
