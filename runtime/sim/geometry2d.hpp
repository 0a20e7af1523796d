#pragma once
// The arena's static geometry in the plane, precomputed into flat arrays: exact ray casts
// (for the IR sensors) and signed clearances (for collisions and free start poses) against
// the walled rectangle, rotated boxes and cylinders. The arena never moves, so these 2D
// answers are exact and much cheaper than Bullet's ray tests.
#include <limits>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

class StaticGeometry2D {
 public:
  explicit StaticGeometry2D(const ArenaSpec& arena);

  static constexpr double kNoHit = std::numeric_limits<double>::infinity();

  // Signed distance from `p` to the nearest wall or obstacle surface (negative inside an
  // obstacle or beyond a wall). Shapes farther than `cutoff_m` may be skipped: the result
  // is exact whenever it is below `cutoff_m`, else some value >= cutoff_m.
  [[nodiscard]] double clearance(Vec2 p, double cutoff_m = kNoHit) const noexcept;

  // The same, counting only the obstacles (boxes and cylinders), not the walls; kNoHit in
  // an arena without obstacles.
  [[nodiscard]] double obstacle_clearance(Vec2 p, double cutoff_m = kNoHit) const noexcept;

  // Casts `n` rays (origins ox/oy, unit directions dx/dy, length max_t) and lowers
  // t[i] to the distance of the first hit of ray i (0 if its origin is inside a shape).
  // Only shapes within `reach_m` of `centre` are tested; every ray must lie in that disc.
  void cast_rays(Vec2 centre, double reach_m, int n, const double* ox, const double* oy,
                 const double* dx, const double* dy, double* t) const noexcept;

 private:
  [[nodiscard]] double clearance_from(double best, Vec2 p, double cutoff_m) const noexcept;

  struct Box {    // centre, half extents, rotation as cos/sin, bounding radius
    double cx, cy, hx, hy, c, s, bound;
  };
  struct Circle {
    double cx, cy, r;
  };
  double width_;
  double height_;
  std::vector<Box> boxes_;
  std::vector<Circle> circles_;
};

}  // namespace esc::sim
