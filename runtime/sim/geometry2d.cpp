#include "runtime/sim/geometry2d.hpp"

#include <algorithm>
#include <cmath>

namespace esc::sim {

StaticGeometry2D::StaticGeometry2D(const ArenaSpec& arena)
    : width_(arena.width_m), height_(arena.height_m) {
  boxes_.reserve(arena.boxes.size());
  for (const BoxObstacle& b : arena.boxes) {
    const double hx = 0.5 * b.size_m.x;
    const double hy = 0.5 * b.size_m.y;
    boxes_.push_back({b.center_m.x, b.center_m.y, hx, hy, std::cos(b.angle_rad),
                      std::sin(b.angle_rad), std::hypot(hx, hy)});
  }
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

void StaticGeometry2D::cast_rays(Vec2 centre, double reach_m, int n, const double* ox,
                                 const double* oy, const double* dx, const double* dy,
                                 double* t) const noexcept {
  // Walls: the ray leaves the rectangle [0, w] x [0, h] at the smallest exit distance.
  if (centre.x < reach_m || width_ - centre.x < reach_m || centre.y < reach_m ||
      height_ - centre.y < reach_m) {
    for (int i = 0; i < n; ++i) {
      double exit = kNoHit;
      if (dx[i] > 0.0) exit = std::min(exit, (width_ - ox[i]) / dx[i]);
      if (dx[i] < 0.0) exit = std::min(exit, -ox[i] / dx[i]);
      if (dy[i] > 0.0) exit = std::min(exit, (height_ - oy[i]) / dy[i]);
      if (dy[i] < 0.0) exit = std::min(exit, -oy[i] / dy[i]);
      t[i] = std::min(t[i], std::max(exit, 0.0));
    }
  }
  for (const Circle& c : circles_) {
    const double ex = centre.x - c.cx;
    const double ey = centre.y - c.cy;
    const double reach = reach_m + c.r;
    if (ex * ex + ey * ey > reach * reach) continue;
    const double r2 = c.r * c.r;
    for (int i = 0; i < n; ++i) {
      const double px = ox[i] - c.cx;
      const double py = oy[i] - c.cy;
      const double cc = px * px + py * py - r2;
      if (cc <= 0.0) {  // origin inside the cylinder
        t[i] = 0.0;
        continue;
      }
      const double b = px * dx[i] + py * dy[i];
      if (b >= 0.0) continue;  // pointing away from the centre and outside
      const double disc = b * b - cc;
      if (disc < 0.0) continue;
      t[i] = std::min(t[i], -b - std::sqrt(disc));
    }
  }
  for (const Box& bx : boxes_) {
    const double ex = centre.x - bx.cx;
    const double ey = centre.y - bx.cy;
    const double reach = reach_m + bx.bound;
    if (ex * ex + ey * ey > reach * reach) continue;
    for (int i = 0; i < n; ++i) {
      // Origin and direction in the box frame, then the slab test.
      const double wx = ox[i] - bx.cx;
      const double wy = oy[i] - bx.cy;
      const double px = bx.c * wx + bx.s * wy;
      const double py = -bx.s * wx + bx.c * wy;
      const double ux = bx.c * dx[i] + bx.s * dy[i];
      const double uy = -bx.s * dx[i] + bx.c * dy[i];
      double lo = -kNoHit;
      double hi = kNoHit;
      if (ux != 0.0) {
        const double a = (-bx.hx - px) / ux;
        const double b = (bx.hx - px) / ux;
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
      } else if (std::abs(px) > bx.hx) {
        continue;
      }
      if (uy != 0.0) {
        const double a = (-bx.hy - py) / uy;
        const double b = (bx.hy - py) / uy;
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
      } else if (std::abs(py) > bx.hy) {
        continue;
      }
      if (hi < 0.0 || lo > hi) continue;
      t[i] = std::min(t[i], std::max(lo, 0.0));
    }
  }
}

}  // namespace esc::sim
