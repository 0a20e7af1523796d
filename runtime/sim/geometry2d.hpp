#pragma once
// The arena's static geometry in the plane, precomputed into flat arrays: exact ray casts
// (for the IR sensors and rangefinders) and signed clearances (for collisions and free start
// poses) against the walled rectangle, rotated boxes, segment walls (their rectangles,
// wall_box, kept with the boxes) and cylinders. The arena never moves, so these 2D answers
// are exact and much cheaper than Bullet's ray tests.
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

// Where a ray from (ox, oy) along the unit (dx, dy) first meets the circle of radius^2 r2 about
// (cx, cy); 0 from an origin inside it, infinity when it misses.
[[nodiscard]] inline double ray_circle_hit(double cx, double cy, double r2, double ox, double oy, double dx, double dy) noexcept {
  const double px = ox - cx;
  const double py = oy - cy;
  const double cc = px * px + py * py - r2;
  if (cc <= 0.0) return 0.0;  // origin inside the cylinder
  const double b = px * dx + py * dy;
  if (b >= 0.0) return std::numeric_limits<double>::infinity();  // pointing away from the centre and outside
  const double disc = b * b - cc;
  if (disc < 0.0) return std::numeric_limits<double>::infinity();
  return -b - std::sqrt(disc);
}

class StaticGeometry2D {
 public:
  explicit StaticGeometry2D(const ArenaSpec& arena);

  static constexpr double kNoHit = std::numeric_limits<double>::infinity();

  // Signed distance from `p` to the nearest wall or obstacle surface (negative inside an
  // obstacle or beyond a wall). Shapes farther than `cutoff_m` may be skipped: the result
  // is exact whenever it is below `cutoff_m`, else some value >= cutoff_m.
  [[nodiscard]] double clearance(Vec2 p, double cutoff_m = kNoHit) const noexcept;

  // The same for a convex polygon (vertices counter-clockwise, in the arena's frame): its
  // distance to the nearest wall or obstacle, exact when positive and below `cutoff_m`, at
  // most 0 when the polygon reaches one (how deep is not measured).
  [[nodiscard]] double clearance(std::span<const Vec2> polygon, double cutoff_m = kNoHit) const noexcept;

  // The point of the walls and obstacles nearest to `p`, or, from inside one, the nearest
  // point of its surface: where a disc centred on `p` touches.
  [[nodiscard]] Vec2 nearest_point(Vec2 p) const noexcept;
  // Where a convex polygon (counter-clockwise, in the arena's frame) comes nearest to the walls
  // and obstacles: the point of theirs nearest to it, exact when apart; overlapping, the point
  // of a vertex's deepest reach.
  [[nodiscard]] Vec2 nearest_point(std::span<const Vec2> polygon) const noexcept;

  // The same, counting only the obstacles (boxes, segment walls and cylinders), not the
  // walled rectangle; kNoHit in an arena without obstacles.
  [[nodiscard]] double obstacle_clearance(Vec2 p, double cutoff_m = kNoHit) const noexcept;

  // Casts `n` rays (origins ox/oy, unit directions dx/dy, length max_t) and lowers
  // t[i] to the distance of the first hit of ray i (0 if its origin is inside a shape).
  // Only shapes within `reach_m` of `centre` are tested; every ray must lie in that disc.
  void cast_rays(Vec2 centre, double reach_m, int n, const double* ox, const double* oy,
                 const double* dx, const double* dy, double* t) const noexcept;

  // The walls and obstacles within some reach of a point, found once for several fans of
  // rays (the IR sensors); sized for every obstacle by nearby(), so gathering never allocates.
  struct Walls {
    bool left = false, right = false, bottom = false, top = false;
    [[nodiscard]] bool any() const noexcept { return left || right || bottom || top; }
  };
  struct Nearby {
    Walls walls;
    std::vector<std::uint32_t> circles, boxes;   // obstacle indices
    [[nodiscard]] bool empty() const noexcept { return !walls.any() && circles.empty() && boxes.empty(); }
  };
  [[nodiscard]] Nearby nearby() const;
  // Every wall and obstacle: for fans cast from the centre of the reach they would be gathered
  // for, where cast_fan's own culls by the fan's origin keep gather's shapes and those beyond
  // the reach by at most kFanMargin_m. Those can lower no reading: a hit on them lies beyond
  // the reach unless a ray's computed direction is longer than 1 by rounding and the shape
  // lies within that rounding of the reach (about 1e-16 of it), where the last bit may differ.
  [[nodiscard]] Nearby everything() const;
  // The shapes cast_rays(centre, reach_m, ...) tests.
  void gather(Vec2 centre, double reach_m, Nearby& out) const noexcept;

  // Lowers t[i] for `n` rays from one origin exactly as cast_rays does, against the shapes
  // of `near` (gathered for a reach that holds every ray), skipping those farther than
  // `range_m` from the origin: when every t[i] <= range_m they cannot lower it.
  void cast_fan(const Nearby& near, Vec2 origin, double range_m, int n, const double* dx, const double* dy,
                double* t) const noexcept;
  // Whether cast_fan from `origin` tests any shape at all (when not, it changes no t).
  [[nodiscard]] bool fan_meets_any(const Nearby& near, Vec2 origin, double range_m) const noexcept {
    if (fan_walls(near, origin, range_m).any()) return true;
    for (const std::uint32_t k : near.circles)
      if (fan_meets_circle(k, origin, range_m)) return true;
    for (const std::uint32_t k : near.boxes)
      if (fan_meets_box(k, origin, range_m)) return true;
    return false;
  }

 private:
  [[nodiscard]] double clearance_from(double best, Vec2 p, double cutoff_m) const noexcept;

  struct Box {    // centre, half extents, rotation as cos/sin, bounding radius
    double cx, cy, hx, hy, c, s, bound;
  };
  // Where a ray first meets the box (0 from inside it), kNoHit if it does not.
  [[nodiscard]] static double box_hit(const Box& b, double ox, double oy, double dx, double dy) noexcept;
  // The same from the ray's origin (px, py) in the box's frame.
  [[nodiscard]] static double box_frame_hit(const Box& b, double px, double py, double dx, double dy) noexcept;
  // cast_fan's rays against box k, the fan's origin at (px, py) in its frame, gap2 from it.
  void fan_box(std::uint32_t k, double px, double py, double gap2, int n, const double* dx, const double* dy,
               double* t) const noexcept;
  [[nodiscard]] bool near_walls(Vec2 centre, double reach_m) const noexcept;
  // Whether the offset (ex, ey) is no longer than reach_m.
  [[nodiscard]] static bool within(double ex, double ey, double reach_m) noexcept {
    return ex * ex + ey * ey <= reach_m * reach_m;
  }
  // cast_fan's tests: which of `near`'s walls and obstacles a fan of rays of length at most
  // range_m from `origin` may meet. A shape farther than range_m from the origin, by a margin
  // far above rounding, is met beyond every t if at all; for a wall, the distance along a
  // unit direction to its line, (w - x) / dx with 0 < dx <= 1, is never below w - x.
  static constexpr double kFanMargin_m = 1e-9;
  [[nodiscard]] Walls fan_walls(const Nearby& near, Vec2 origin, double range_m) const noexcept {
    const double limit_m = range_m + kFanMargin_m;
    return {near.walls.left && origin.x < limit_m, near.walls.right && width_ - origin.x < limit_m,
            near.walls.bottom && origin.y < limit_m, near.walls.top && height_ - origin.y < limit_m};
  }
  [[nodiscard]] bool fan_meets_circle(std::uint32_t k, Vec2 origin, double range_m) const noexcept {
    const Circle& c = circles_[k];
    return within(origin.x - c.cx, origin.y - c.cy, range_m + kFanMargin_m + c.r);
  }
  [[nodiscard]] bool fan_meets_box(std::uint32_t k, Vec2 origin, double range_m) const noexcept {
    const Box& b = boxes_[k];
    return within(origin.x - b.cx, origin.y - b.cy, range_m + kFanMargin_m + b.bound);
  }
  struct Circle {
    double cx, cy, r;
  };
  double width_;
  double height_;
  std::vector<Box> boxes_;
  std::vector<Circle> circles_;
};

}  // namespace esc::sim
