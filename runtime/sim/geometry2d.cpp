#include "runtime/sim/geometry2d.hpp"

#include <algorithm>
#include <cmath>

namespace esc::sim {

StaticGeometry2D::StaticGeometry2D(const ArenaSpec& arena)
    : width_(arena.width_m), height_(arena.height_m) {
  boxes_.reserve(arena.boxes.size() + arena.walls.size());
  const auto add_box = [this](const BoxObstacle& b) {
    const double hx = 0.5 * b.size_m.x;
    const double hy = 0.5 * b.size_m.y;
    boxes_.push_back({b.center_m.x, b.center_m.y, hx, hy, std::cos(b.angle_rad),
                      std::sin(b.angle_rad), std::hypot(hx, hy)});
  };
  for (const BoxObstacle& b : arena.boxes) add_box(b);
  for (const WallSegment& w : arena.walls) add_box(wall_box(w));
  circles_.reserve(arena.cylinders.size());
  for (const CylinderObstacle& c : arena.cylinders)
    circles_.push_back({c.center_m.x, c.center_m.y, c.radius_m});
}

double StaticGeometry2D::clearance(Vec2 p, double cutoff_m) const noexcept {
  return clearance_from(std::min(std::min(p.x, width_ - p.x), std::min(p.y, height_ - p.y)), p,
                        cutoff_m);
}

double StaticGeometry2D::obstacle_clearance(Vec2 p, double cutoff_m) const noexcept {
  return clearance_from(kNoHit, p, cutoff_m);
}

double StaticGeometry2D::clearance_from(double best, Vec2 p, double cutoff_m) const noexcept {
  for (const Circle& c : circles_) {
    const double ex = p.x - c.cx;
    const double ey = p.y - c.cy;
    const double reach = std::min(best, cutoff_m) + c.r;
    if (ex * ex + ey * ey > reach * reach && reach > 0.0) continue;
    best = std::min(best, std::sqrt(ex * ex + ey * ey) - c.r);
  }
  for (const Box& b : boxes_) {
    const double ex = p.x - b.cx;
    const double ey = p.y - b.cy;
    const double reach = std::min(best, cutoff_m) + b.bound;
    if (ex * ex + ey * ey > reach * reach && reach > 0.0) continue;
    const double qx = std::abs(b.c * ex + b.s * ey) - b.hx;  // box frame
    const double qy = std::abs(-b.s * ex + b.c * ey) - b.hy;
    const double ox = std::max(qx, 0.0);
    const double oy = std::max(qy, 0.0);
    const double d = std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
    best = std::min(best, d);
  }
  return best;
}

namespace {

// What one ray meets, as a distance that may lower its t: each kernel gives kNoHit where it
// meets nothing.

// Where a ray from (ox, oy) along (dx, dy) leaves the walled rectangle [0, w] x [0, h] through
// one of `walls`, not before its origin (0 from an origin beyond a wall).
inline double wall_exit(double w, double h, StaticGeometry2D::Walls walls, double ox, double oy, double dx,
                        double dy) noexcept {
  double exit = StaticGeometry2D::kNoHit;
  if (walls.right && dx > 0.0) exit = std::min(exit, (w - ox) / dx);
  if (walls.left && dx < 0.0) exit = std::min(exit, -ox / dx);
  if (walls.top && dy > 0.0) exit = std::min(exit, (h - oy) / dy);
  if (walls.bottom && dy < 0.0) exit = std::min(exit, -oy / dy);
  return std::max(exit, 0.0);
}

// The first point of a circle of radius^2 r2 about (cx, cy); 0 from an origin inside it.
inline double circle_hit(double cx, double cy, double r2, double ox, double oy, double dx, double dy) noexcept {
  const double px = ox - cx;
  const double py = oy - cy;
  const double cc = px * px + py * py - r2;
  if (cc <= 0.0) return 0.0;  // origin inside the cylinder
  const double b = px * dx + py * dy;
  if (b >= 0.0) return StaticGeometry2D::kNoHit;  // pointing away from the centre and outside
  const double disc = b * b - cc;
  if (disc < 0.0) return StaticGeometry2D::kNoHit;
  return -b - std::sqrt(disc);
}

// One slab of the box test, along one box axis: narrows [lo, hi] to the ray parameters
// within `half` of the centre (origin p, direction u along that axis); false when the ray
// runs parallel to the slab outside it.
// Rounding room of the ray cull: a ray is skipped only when its nearest hit so far is nearer
// than the bounding circle by more than this (far above rounding, far below any geometry).
constexpr double kCullMargin_m = 1e-9;

bool clip_slab(double p, double u, double half, double& lo, double& hi) noexcept {
  if (u == 0.0) return std::abs(p) <= half;
  const double a = (-half - p) / u;
  const double b = (half - p) / u;
  lo = std::max(lo, std::min(a, b));
  hi = std::min(hi, std::max(a, b));
  return true;
}

}  // namespace

double StaticGeometry2D::box_hit(const Box& bx, double ox, double oy, double dx, double dy) noexcept {
  // Origin and direction in the box frame, then the slab test.
  const double wx = ox - bx.cx;
  const double wy = oy - bx.cy;
  return box_frame_hit(bx, bx.c * wx + bx.s * wy, -bx.s * wx + bx.c * wy, dx, dy);
}

double StaticGeometry2D::box_frame_hit(const Box& bx, double px, double py, double dx, double dy) noexcept {
  const double ux = bx.c * dx + bx.s * dy;
  const double uy = -bx.s * dx + bx.c * dy;
  double lo = -kNoHit;
  double hi = kNoHit;
  if (!clip_slab(px, ux, bx.hx, lo, hi) || !clip_slab(py, uy, bx.hy, lo, hi)) return kNoHit;
  if (hi < 0.0 || lo > hi) return kNoHit;
  return std::max(lo, 0.0);
}

bool StaticGeometry2D::near_walls(Vec2 centre, double reach_m) const noexcept {
  return centre.x < reach_m || width_ - centre.x < reach_m || centre.y < reach_m || height_ - centre.y < reach_m;
}

void StaticGeometry2D::cast_rays(Vec2 centre, double reach_m, int n, const double* ox,
                                 const double* oy, const double* dx, const double* dy,
                                 double* t) const noexcept {
  if (near_walls(centre, reach_m)) {
    const Walls all{true, true, true, true};
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], wall_exit(width_, height_, all, ox[i], oy[i], dx[i], dy[i]));
  }
  for (const Circle& c : circles_) {
    if (!within(centre.x - c.cx, centre.y - c.cy, reach_m + c.r)) continue;
    const double r2 = c.r * c.r;
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], circle_hit(c.cx, c.cy, r2, ox[i], oy[i], dx[i], dy[i]));
  }
  for (const Box& bx : boxes_) {
    if (!within(centre.x - bx.cx, centre.y - bx.cy, reach_m + bx.bound)) continue;
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], box_hit(bx, ox[i], oy[i], dx[i], dy[i]));
  }
}

StaticGeometry2D::Nearby StaticGeometry2D::nearby() const {
  Nearby n;
  n.circles.reserve(circles_.size());
  n.boxes.reserve(boxes_.size());
  return n;
}

void StaticGeometry2D::gather(Vec2 centre, double reach_m, Nearby& out) const noexcept {
  const bool walls = near_walls(centre, reach_m);
  out.walls = {walls, walls, walls, walls};
  out.circles.clear();
  out.boxes.clear();
  for (std::size_t i = 0; i < circles_.size(); ++i)
    if (within(centre.x - circles_[i].cx, centre.y - circles_[i].cy, reach_m + circles_[i].r))
      out.circles.push_back(static_cast<std::uint32_t>(i));
  for (std::size_t i = 0; i < boxes_.size(); ++i)
    if (within(centre.x - boxes_[i].cx, centre.y - boxes_[i].cy, reach_m + boxes_[i].bound))
      out.boxes.push_back(static_cast<std::uint32_t>(i));
}

void StaticGeometry2D::cast_fan(const Nearby& near, Vec2 origin, double range_m, int n, const double* dx,
                                const double* dy, double* t) const noexcept {
  const Walls walls = fan_walls(near, origin, range_m);
  if (walls.any())
    for (int i = 0; i < n; ++i)
      t[i] = std::min(t[i], wall_exit(width_, height_, walls, origin.x, origin.y, dx[i], dy[i]));
  for (const std::uint32_t k : near.circles) {
    if (!fan_meets_circle(k, origin, range_m)) continue;
    const Circle& c = circles_[k];
    const double r2 = c.r * c.r;
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], circle_hit(c.cx, c.cy, r2, origin.x, origin.y, dx[i], dy[i]));
  }
  for (const std::uint32_t k : near.boxes) {
    if (!fan_meets_box(k, origin, range_m)) continue;
    // The fan's origin in the box's frame, once; a ray whose nearest hit so far is no farther
    // than the box's bounding circle cannot meet the box nearer (its min stays as it is).
    const Box& bx = boxes_[k];
    const double wx = origin.x - bx.cx;
    const double wy = origin.y - bx.cy;
    const double px = bx.c * wx + bx.s * wy;
    const double py = -bx.s * wx + bx.c * wy;
    const double nearest = std::sqrt(wx * wx + wy * wy) - bx.bound - kCullMargin_m;
    for (int i = 0; i < n; ++i)
      if (t[i] > nearest) t[i] = std::min(t[i], box_frame_hit(bx, px, py, dx[i], dy[i]));
  }
}

}  // namespace esc::sim
