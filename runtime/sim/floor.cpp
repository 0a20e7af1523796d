#include "runtime/sim/floor.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace esc::sim {

namespace {

// Random-zone rejection sampling gives up after this many draws per zone.
constexpr int kZonePlacementTries = 10000;
// The sweep grid has ceil(size / cell - this) columns (rows), so that a size that is a whole
// number of cells up to rounding (0.6 / 0.04) gets no sliver column.
constexpr double kSweepCellRounding = 1e-9;

int grid_count(double size_m, double cell_m) {
  return std::max(1, static_cast<int>(std::ceil(size_m / cell_m - kSweepCellRounding)));
}

}  // namespace

Floor::Floor(const ArenaSpec& arena, const RobotParams& robot) : arena_(arena) {
  const std::size_t nz = arena_.zones.size();
  zones_.resize(nz);
  zone_centers_.resize(nz);
  for (std::size_t i = 0; i < nz; ++i) {
    const Zone& z = arena_.zones[i];
    ZoneGeom& g = zones_[i];
    g.circle = z.shape == ZoneShape::Circle;
    g.hx = g.circle ? z.radius_m : 0.5 * z.size_m.x;
    g.hy = g.circle ? z.radius_m : 0.5 * z.size_m.y;
    g.r2 = z.radius_m * z.radius_m;
    const Vec2 c = z.random_position ? Vec2{arena_.width_m / 2, arena_.height_m / 2} : z.center_m;
    g.cx = c.x;
    g.cy = c.y;
    zone_centers_[i] = c;
    if (z.recharge) recharge_mask_ |= 1U << i;
    if (z.visible) visible_mask_ |= 1U << i;
  }
  lights_.resize(arena_.lights.size());
  light_positions_.resize(arena_.lights.size());
  for (std::size_t l = 0; l < arena_.lights.size(); ++l) {
    lights_[l].height_m = arena_.lights[l].height_m;
    lights_[l].intensity = arena_.lights[l].intensity;
  }
  place_lights();
  reach2_m2_ = arena_.reach_radius_m * arena_.reach_radius_m;
  energy_on_ = robot.energy.enabled;
  energy_drain_ = robot.energy.recharge_steps;
  energy_gain_ = robot.energy.discharge_steps;
  energy_full_ = static_cast<std::int64_t>(robot.energy.discharge_steps) * robot.energy.recharge_steps *
                 robot.physics_substeps;
  energy_units_ = energy_full_;
  sweep_cols_ = grid_count(arena_.width_m, arena_.sweep_cell_m);
  sweep_rows_ = grid_count(arena_.height_m, arena_.sweep_cell_m);
  const auto cells = static_cast<std::size_t>(sweep_cols_) * static_cast<std::size_t>(sweep_rows_);
  visited_.assign((cells + 63) / 64, 0);
}

// Lights above a zone stand at its centre; the others where the arena says.
void Floor::place_lights() {
  for (std::size_t l = 0; l < arena_.lights.size(); ++l) {
    const LightSource& src = arena_.lights[l];
    const Vec2 p = src.above_zone >= 0 ? zone_centers_[static_cast<std::size_t>(src.above_zone)] : src.position_m;
    lights_[l].x_m = p.x;
    lights_[l].y_m = p.y;
    light_positions_[l] = p;
  }
}

void Floor::place_zones(Rng& rng, const StaticGeometry2D& geometry) {
  bool moved = false;
  for (std::size_t i = 0; i < arena_.zones.size(); ++i) {
    if (!arena_.zones[i].random_position) continue;
    ZoneGeom& g = zones_[i];
    // Clear of obstacles: a circle exactly, a rectangle by its circumscribed circle.
    const double keep = g.circle ? std::sqrt(g.r2) : std::hypot(g.hx, g.hy);
    bool placed = false;
    for (int t = 0; t < kZonePlacementTries && !placed; ++t) {
      const double x = rng.uniform(g.hx, arena_.width_m - g.hx);
      const double y = rng.uniform(g.hy, arena_.height_m - g.hy);
      if (geometry.obstacle_clearance({x, y}, keep) >= keep) {
        g.cx = x;
        g.cy = y;
        zone_centers_[i] = {x, y};
        placed = true;
      }
    }
    if (!placed)
      throw std::runtime_error("arena.zones[" + std::to_string(i) +
                               "] has no free place: no position found that keeps it inside "
                               "the arena and clear of every obstacle");
    moved = true;
  }
  if (moved) place_lights();
}

void Floor::take_zones(const Floor& other) {
  zones_ = other.zones_;
  zone_centers_ = other.zone_centers_;
  lights_ = other.lights_;
  light_positions_ = other.light_positions_;
}

bool Floor::in_recharge(double x, double y) const noexcept {
  for (std::uint32_t m = recharge_mask_; m != 0; m &= m - 1)
    if (zones_[static_cast<std::size_t>(std::countr_zero(m))].contains(x, y)) return true;
  return false;
}

bool Floor::in_zone(std::size_t zone, Vec2 p) const noexcept {
  return zone < zones_.size() && zones_[zone].contains(p.x, p.y);
}

bool Floor::visible_at(Vec2 p) const noexcept {
  for (std::uint32_t m = visible_mask_; m != 0; m &= m - 1)
    if (zones_[static_cast<std::size_t>(std::countr_zero(m))].contains(p.x, p.y)) return true;
  return false;
}

void Floor::reset(Vec2 centre, FloorState& state) {
  state = FloorState{};
  energy_units_ = energy_full_;
  std::fill(visited_.begin(), visited_.end(), std::uint64_t{0});
  read(centre, true, state);
}

void Floor::drain_or_recharge(Vec2 centre) noexcept {
  energy_units_ = in_recharge(centre.x, centre.y) ? std::min(energy_full_, energy_units_ + energy_gain_)
                                                  : std::max(std::int64_t{0}, energy_units_ - energy_drain_);
}

void Floor::observe(Vec2 centre, FloorState& state) noexcept { read(centre, false, state); }

void Floor::read(Vec2 centre, bool fresh, FloorState& state) noexcept {
  const double x = centre.x;
  const double y = centre.y;
  std::uint32_t in = 0;
  for (std::size_t i = 0; i < zones_.size(); ++i)
    if (zones_[i].contains(x, y)) in |= 1U << i;
  state.in_zone = in;
  state.ground = (in & visible_mask_) != 0;
  std::uint32_t near = 0;
  for (std::size_t l = 0; l < lights_.size(); ++l) {
    const double dx = x - lights_[l].x_m;
    const double dy = y - lights_[l].y_m;
    if (dx * dx + dy * dy <= reach2_m2_) near |= 1U << l;
  }
  state.reached = fresh ? 0U : near & ~inside_reach_;
  for (std::uint32_t m = state.reached; m != 0; m &= m - 1)
    ++state.reach_count[static_cast<std::size_t>(std::countr_zero(m))];
  inside_reach_ = near;
  const double cell_m = arena_.sweep_cell_m;
  const int col = std::clamp(static_cast<int>(std::floor(x / cell_m)), 0, sweep_cols_ - 1);
  const int row = std::clamp(static_cast<int>(std::floor(y / cell_m)), 0, sweep_rows_ - 1);
  const auto cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(sweep_cols_) +
                    static_cast<std::size_t>(col);
  const std::uint64_t bit = std::uint64_t{1} << (cell % 64);
  std::uint64_t& word = visited_[cell / 64];
  state.new_cell = (word & bit) == 0 && !fresh;
  if ((word & bit) == 0) {
    word |= bit;
    ++state.cells_visited;
  }
  state.energy = energy_units_ == energy_full_
                     ? 1.0
                     : static_cast<double>(energy_units_) / static_cast<double>(energy_full_);
  state.energy_empty = energy_on_ && energy_units_ == 0;
}

}  // namespace esc::sim
