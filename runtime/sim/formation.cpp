#include "runtime/sim/formation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "runtime/sim/geometry2d.hpp"

namespace esc::sim {

Pose formation_pose(const Formation& f, std::size_t n, std::size_t i, Vec2 centre, double heading) noexcept {
  if (f.kind == FormationKind::Circle) {
    const double a = heading + 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    return {centre.x + f.spacing_m * std::cos(a), centre.y + f.spacing_m * std::sin(a), std::remainder(a, 2.0 * std::numbers::pi)};
  }
  // Side by side: along the heading's left normal, robot 0 on the left end.
  const double offset = (static_cast<double>(n - 1) / 2.0 - static_cast<double>(i)) * f.spacing_m;
  return {centre.x - offset * std::sin(heading), centre.y + offset * std::cos(heading), heading};
}

double formation_reach(const Formation& f, std::size_t n) noexcept {
  if (f.kind == FormationKind::Circle) return f.spacing_m;
  return static_cast<double>(n - 1) / 2.0 * f.spacing_m;
}

double formation_closest(const Formation& f, std::size_t n) noexcept {
  if (n < 2) return std::numeric_limits<double>::infinity();
  if (f.kind == FormationKind::Circle) return 2.0 * f.spacing_m * std::sin(std::numbers::pi / static_cast<double>(n));
  return f.spacing_m;
}

std::string formation_problem(const Formation& f, const ArenaSpec& arena, std::span<const double> radii_m,
                              double margin_m) {
  const std::size_t n = radii_m.size();
  const auto metres = [](double v) { return fmt::format("{:g} cm", v * 100); };
  if (f.kind == FormationKind::Random) return {};
  if (f.kind == FormationKind::At) {
    if (f.at.size() != n) return fmt::format("it gives {} poses for {} robots: one per robot", f.at.size(), n);
    const StaticGeometry2D geometry(arena);
    for (std::size_t i = 0; i < n; ++i) {
      const Pose& p = f.at[i];
      const double keep = radii_m[i] + margin_m;
      if (p.x_m < keep || p.y_m < keep || p.x_m > arena.width_m - keep || p.y_m > arena.height_m - keep ||
          !(geometry.clearance({p.x_m, p.y_m}, keep) >= keep))
        return fmt::format("robot {} at ({}, {}) is not {} clear of every wall and obstacle", i + 1, metres(p.x_m),
                           metres(p.y_m), metres(margin_m));
      for (std::size_t j = 0; j < i; ++j)
        if (std::hypot(p.x_m - f.at[j].x_m, p.y_m - f.at[j].y_m) < radii_m[i] + radii_m[j] + margin_m)
          return fmt::format("robots {} and {} would start overlapping", j + 1, i + 1);
    }
    return {};
  }
  // A line's or a circle's places are every robot's alike: each kept as the largest body is.
  const auto [smallest, largest] = std::minmax_element(radii_m.begin(), radii_m.end());
  const double radius_m = n == 0 ? 0.0 : *largest;
  const double keep = radius_m + margin_m;
  if (!(f.spacing_m > 0.0)) return "its spacing must be a length greater than 0";
  if (formation_closest(f, n) < 2 * radius_m + margin_m)
    return fmt::format("neighbours {} apart would overlap ({} {}, kept {} apart)", metres(formation_closest(f, n)),
                       *smallest == *largest ? "robots of radius" : "the largest robot's radius", metres(radius_m),
                       metres(margin_m));
  const double across = 2 * (formation_reach(f, n) + keep);
  if (across > arena.width_m || across > arena.height_m)
    return fmt::format("it is {} across and the arena {} x {}", metres(across), metres(arena.width_m),
                       metres(arena.height_m));
  return {};
}

}  // namespace esc::sim
