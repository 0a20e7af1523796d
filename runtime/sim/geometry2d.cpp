#include "runtime/sim/geometry2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace esc::sim {

namespace {

// Where the point q (from a) projects on segment e (from a), as a fraction of it in [0, 1].
double segment_fraction(Vec2 q, Vec2 e) noexcept {
  const double len2 = e.x * e.x + e.y * e.y;
  return len2 > 0.0 ? std::clamp((q.x * e.x + q.y * e.y) / len2, 0.0, 1.0) : 0.0;
}

// The distance from p to segment ab.
double point_segment(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 e = minus(b, a), q = minus(p, a);
  const double t = segment_fraction(q, e);
  return std::hypot(q.x - t * e.x, q.y - t * e.y);
}

// The point of segment ab nearest to p.
Vec2 segment_point(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 e = minus(b, a);
  const double t = segment_fraction(minus(p, a), e);
  return {a.x + t * e.x, a.y + t * e.y};
}

// Whether segments ab and cd share a point (touching counts).
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  const double d1 = cross(minus(b, a), minus(c, a)), d2 = cross(minus(b, a), minus(d, a));
  const double d3 = cross(minus(d, c), minus(a, c)), d4 = cross(minus(d, c), minus(b, c));
  return ((d1 <= 0.0 && d2 >= 0.0) || (d1 >= 0.0 && d2 <= 0.0)) && ((d3 <= 0.0 && d4 >= 0.0) || (d3 >= 0.0 && d4 <= 0.0));
}

// Whether p lies in a convex counter-clockwise polygon (its edges count).
bool polygon_holds(std::span<const Vec2> poly, Vec2 p) noexcept {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (cross(minus(poly[(i + 1) % poly.size()], poly[i]), minus(p, poly[i])) < 0.0) return false;
  return true;
}

// The distance between two convex counter-clockwise polygons, 0 when they meet: apart, it is
// a vertex of one against an edge of the other.
double polygon_distance(std::span<const Vec2> a, std::span<const Vec2> b) noexcept {
  if (polygon_holds(b, a[0]) || polygon_holds(a, b[0])) return 0.0;
  double best = StaticGeometry2D::kNoHit;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 a0 = a[i], a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 b0 = b[j], b1 = b[(j + 1) % b.size()];
      if (segments_meet(a0, a1, b0, b1)) return 0.0;
      best = std::min({best, point_segment(a0, b0, b1), point_segment(b0, a0, a1)});
    }
  }
  return best;
}

}  // namespace

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

double StaticGeometry2D::clearance(std::span<const Vec2> polygon, double cutoff_m) const noexcept {
  // The walled rectangle: a convex polygon comes nearest it at a vertex.
  double best = kNoHit;
  Vec2 centre;
  for (const Vec2& v : polygon) {
    best = std::min({best, v.x, width_ - v.x, v.y, height_ - v.y});
    centre = {centre.x + v.x / static_cast<double>(polygon.size()), centre.y + v.y / static_cast<double>(polygon.size())};
  }
  double bound = 0.0;   // the polygon lies within this of `centre`
  for (const Vec2& v : polygon) bound = std::max(bound, std::hypot(v.x - centre.x, v.y - centre.y));
  for (const Circle& c : circles_) {
    if (!within(centre.x - c.cx, centre.y - c.cy, bound + c.r + std::min(best, cutoff_m))) continue;
    const Vec2 p{c.cx, c.cy};
    if (polygon_holds(polygon, p)) return -c.r;
    for (std::size_t i = 0; i < polygon.size(); ++i)
      best = std::min(best, point_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]) - c.r);
  }
  for (const Box& b : boxes_) {
    if (!within(centre.x - b.cx, centre.y - b.cy, bound + b.bound + std::min(best, cutoff_m))) continue;
    const auto corner = [&b](double x, double y) { return Vec2{b.cx + b.c * x - b.s * y, b.cy + b.s * x + b.c * y}; };
    const Vec2 corners[] = {corner(-b.hx, -b.hy), corner(b.hx, -b.hy), corner(b.hx, b.hy), corner(-b.hx, b.hy)};
    best = std::min(best, polygon_distance(polygon, corners));
  }
  return best;
}

namespace {

// The nearest of candidate contacts (a signed distance and a point of the walls or
// obstacles); those as near within a micrometre are averaged, so that a flat side against a
// wall, met at both its ends, touches in its middle, and a corner of two walls between them.
struct Witness {
  static constexpr double kTie_m = 1e-6;
  double distance = StaticGeometry2D::kNoHit;
  Vec2 sum;
  int count = 0;
  void offer(double d, Vec2 p) noexcept {
    if (d < distance - kTie_m) {
      *this = {d, p, 1};
    } else if (d <= distance + kTie_m) {
      distance = std::min(distance, d);
      sum = {sum.x + p.x, sum.y + p.y};
      ++count;
    }
  }
  [[nodiscard]] Vec2 at() const noexcept { return {sum.x / count, sum.y / count}; }
};

}  // namespace

Vec2 StaticGeometry2D::nearest_point(Vec2 p) const noexcept {
  Witness w;
  w.offer(p.x, {0.0, p.y});
  w.offer(width_ - p.x, {width_, p.y});
  w.offer(p.y, {p.x, 0.0});
  w.offer(height_ - p.y, {p.x, height_});
  for (const Circle& c : circles_) {
    const double ex = p.x - c.cx, ey = p.y - c.cy, d = std::hypot(ex, ey);
    w.offer(d - c.r, d > 0.0 ? Vec2{c.cx + c.r * ex / d, c.cy + c.r * ey / d} : Vec2{c.cx + c.r, c.cy});
  }
  for (const Box& b : boxes_) {
    const double ex = p.x - b.cx, ey = p.y - b.cy;
    const double lx = b.c * ex + b.s * ey, ly = -b.s * ex + b.c * ey;   // box frame
    const double qx = std::abs(lx) - b.hx, qy = std::abs(ly) - b.hy;
    double nx = std::clamp(lx, -b.hx, b.hx), ny = std::clamp(ly, -b.hy, b.hy);
    if (qx <= 0.0 && qy <= 0.0) {   // inside: out through the nearer side
      if (qx > qy) nx = std::copysign(b.hx, lx);
      else ny = std::copysign(b.hy, ly);
    }
    const double d = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
    w.offer(d, {b.cx + b.c * nx - b.s * ny, b.cy + b.s * nx + b.c * ny});
  }
  return w.at();
}

Vec2 StaticGeometry2D::nearest_point(std::span<const Vec2> polygon) const noexcept {
  // Apart, two convex shapes are nearest at a vertex of one against the other: the polygon's
  // vertices against everything, the boxes' corners and the circles against its edges.
  Witness w;
  for (const Vec2& v : polygon) w.offer(clearance(v), nearest_point(v));
  const auto boundary = [&](Vec2 p) {
    Vec2 best = polygon[0];
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2 q = segment_point(p, polygon[i], polygon[(i + 1) % polygon.size()]);
      if (std::hypot(q.x - p.x, q.y - p.y) < std::hypot(best.x - p.x, best.y - p.y)) best = q;
    }
    return best;
  };
  for (const Circle& c : circles_) {
    const Vec2 centre{c.cx, c.cy}, q = boundary(centre);
    const double d = std::hypot(q.x - c.cx, q.y - c.cy);
    if (polygon_holds(polygon, centre)) w.offer(-c.r, centre);
    else if (d > 0.0) w.offer(d - c.r, {c.cx + c.r * (q.x - c.cx) / d, c.cy + c.r * (q.y - c.cy) / d});
  }
  for (const Box& b : boxes_)
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0}) {
        const Vec2 corner{b.cx + b.c * sx * b.hx - b.s * sy * b.hy, b.cy + b.s * sx * b.hx + b.c * sy * b.hy};
        const Vec2 q = boundary(corner);
        w.offer((polygon_holds(polygon, corner) ? -1.0 : 1.0) * std::hypot(q.x - corner.x, q.y - corner.y), corner);
      }
  return w.at();
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


// Rounding room of the ray culls: a ray is skipped only when the box is farther than its
// nearest hit so far, or its line passes the box, by more than this (far above rounding, far
// below any geometry).
constexpr double kCullMargin_m = 1e-9;

// One slab of the box test, along one box axis: narrows [lo, hi] to the ray parameters
// within `half` of the centre (origin p, direction u along that axis); false when the ray
// runs parallel to the slab outside it.
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
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], ray_circle_hit(c.cx, c.cy, r2, ox[i], oy[i], dx[i], dy[i]));
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

StaticGeometry2D::Nearby StaticGeometry2D::everything() const {
  Nearby n{{true, true, true, true}, {}, {}};
  for (std::uint32_t i = 0; i < circles_.size(); ++i) n.circles.push_back(i);
  for (std::uint32_t i = 0; i < boxes_.size(); ++i) n.boxes.push_back(i);
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
    for (int i = 0; i < n; ++i) t[i] = std::min(t[i], ray_circle_hit(c.cx, c.cy, r2, origin.x, origin.y, dx[i], dy[i]));
  }
  const double reach_m = range_m + kCullMargin_m;
  for (const std::uint32_t k : near.boxes) {
    if (!fan_meets_box(k, origin, range_m)) continue;
    const Box& bx = boxes_[k];
    const double wx = origin.x - bx.cx;
    const double wy = origin.y - bx.cy;
    const double px = bx.c * wx + bx.s * wy;
    const double py = -bx.s * wx + bx.c * wy;
    const double ox = std::max(std::abs(px) - bx.hx, 0.0);
    const double oy = std::max(std::abs(py) - bx.hy, 0.0);
    const double gap2 = ox * ox + oy * oy;
    if (gap2 <= reach_m * reach_m) fan_box(k, px, py, gap2, n, dx, dy, t);  // squared: a root's latency showed
  }
}

void StaticGeometry2D::fan_box(std::uint32_t k, double px, double py, double gap2, int n, const double* dx,
                               const double* dy, double* t) const noexcept {
  // The culls skip only rays the box cannot lower, so the t are those of testing every ray: a
  // ray whose nearest hit so far is no farther than the box (gap2, the squared distance to
  // it), one whose line passes the box by more than rounding (the slab test's intervals are
  // then disjoint by far more than its rounding), and one for which the box lies behind the
  // origin or beyond t. A maze's long walls have bounding circles that reach everywhere;
  // these culls do not depend on them.
  const Box& bx = boxes_[k];
  for (int i = 0; i < n; ++i) {
    const double near_m = t[i] + kCullMargin_m;
    if (near_m * near_m <= gap2) continue;
    const double ux = bx.c * dx[i] + bx.s * dy[i];
    const double uy = -bx.s * dx[i] + bx.c * dy[i];
    const double ax = std::abs(ux);
    const double ay = std::abs(uy);
    if (std::abs(ux * py - uy * px) > bx.hx * ay + bx.hy * ax + kCullMargin_m) continue;
    const double along = -(px * ux + py * uy);
    const double half = bx.hx * ax + bx.hy * ay + kCullMargin_m;
    if (along + half < 0.0 || along - half > t[i]) continue;
    t[i] = std::min(t[i], box_frame_hit(bx, px, py, dx[i], dy[i]));
  }
}

}  // namespace esc::sim
