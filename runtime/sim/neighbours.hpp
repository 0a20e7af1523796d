#pragma once
// The other robots of a group, as one robot's rays, contact tests and starts see them: each
// body placed in the plane (a disc, or its outline), and a uniform grid over the arena that
// finds the robots within some reach of a point without testing every pair (a broadphase:
// built once a control step, in linear time, without allocating once sized).
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

// A robot's body at its current pose.
struct PlacedBody {
  Vec2 centre;
  double radius_m = 0.0;            // the disc, or the circle about the centre holding the outline
  std::span<const Vec2> outline;    // counter-clockwise, in the arena's frame; empty for a disc
};

// Where a ray from `origin` along the unit (dx, dy) first meets the body: 0 from inside it,
// infinity when it misses.
[[nodiscard]] double ray_body_hit(const PlacedBody& body, Vec2 origin, double dx, double dy) noexcept;

// Lowers t[i] for `n` rays from `origin` (unit directions dx, dy) to their first hit on any of
// `bodies`; a body beyond every t is not tested further.
void cast_fan_at_bodies(std::span<const PlacedBody> bodies, Vec2 origin, int n, const double* dx, const double* dy,
                        double* t) noexcept;

class Neighbours {
 public:
  // Sizes the grid for `robots` robots in a width x height arena, with cells of at least
  // `cell_m` and no more cells than robots (a query's reach may be any: it visits the cells
  // its square covers).
  Neighbours(std::size_t robots, double width_m, double height_m, double cell_m);

  // The robots' centres now (one outside the arena counts in the cell nearest to it).
  void build(std::span<const Vec2> centres) noexcept;

  // Calls f(j) for every robot j whose centre may lie within `reach_m` of `p` (a superset:
  // those in the cells the square about p covers), each once, in index order within a cell.
  template <class F>
  void near(Vec2 p, double reach_m, F&& f) const {
    const int x0 = column(p.x - reach_m), x1 = column(p.x + reach_m);
    const int y0 = row(p.y - reach_m), y1 = row(p.y + reach_m);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const auto cell = static_cast<std::size_t>(y * columns_ + x);
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(static_cast<std::size_t>(items_[k]));
      }
  }

 private:
  [[nodiscard]] int column(double x) const noexcept { return index(x, columns_); }
  [[nodiscard]] int row(double y) const noexcept { return index(y, rows_); }
  [[nodiscard]] int index(double v, int count) const noexcept {
    const double c = v / cell_m_;
    return c >= 1.0 ? static_cast<int>(std::min(c, static_cast<double>(count - 1))) : 0;   // NaN: 0
  }

  double cell_m_;
  int columns_, rows_;
  std::vector<std::uint32_t> start_;   // robots of cell c: items_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> cell_of_;
};

}  // namespace esc::sim
