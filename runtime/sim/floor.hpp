#pragma once
// What the floor tells about where the robot's centre is: the zones (and where the random
// ones are this epoch), the lights above them and the reach of each light, the energy
// accumulator that recharge zones refill, and the area-sweeping grid. Plain C++ with no
// Bullet: it only reads the centre's position, which the body (body.hpp) provides.
// Model and constants in docs/robot-model.md ("Zones, energy", "Area sweeping").
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/geometry2d.hpp"
#include "runtime/sim/robot_params.hpp"
#include "runtime/sim/light_sensor.hpp"

namespace esc::sim {

// The floor's part of the robot's state after the last control step.
struct FloorState {
  // Energy accumulator, [0, 1]; exactly 1 when the energy model is off. Exact multiples of
  // 1 / (discharge_steps * recharge_steps * physics_substeps).
  double energy = 1.0;
  bool energy_empty = false;               // model on and accumulator empty: the epoch ends
  std::uint32_t in_zone = 0;               // bit i: centre inside zone i (end of the step)
  bool ground = false;                     // centre over a visible zone (the ground sensor)
  std::uint32_t reached = 0;               // bit i: centre came within reach of light i
                                           // during this step (rising edge only)
  std::array<int, kMaxLights> reach_count{};  // entries into each light's reach this epoch
  bool new_cell = false;                   // centre entered a grid cell not visited this epoch
  int cells_visited = 0;                   // grid cells visited this epoch, the start cell included
};

class Floor {
 public:
  // Zones at their declared positions (random ones at the arena's centre until
  // place_zones), lights above them or where the arena says. The arena and robot must have
  // passed validate_arena / validate_robot.
  Floor(const ArenaSpec& arena, const RobotParams& robot);

  // Draws a position for every zone with random_position, in zone index order, uniform over
  // the centres that keep the zone inside the arena and clear of every obstacle of
  // `geometry` (a rectangle by its circumscribed circle), and moves the lights above those
  // zones with them. Draws nothing when no zone is random. Throws std::runtime_error if a
  // zone finds no free place.
  void place_zones(Rng& rng, const StaticGeometry2D& geometry);
  // The zones and lights where `other` (of the same arena) placed them: every robot of a group
  // has a floor of its own (its accumulator, reach counts, sweep grid) over the same zones.
  void take_zones(const Floor& other);

  // The robot placed with its centre at `centre` (World::reset): accumulator full, only the
  // start cell visited, no reach counted (a light whose reach the robot starts in counts only
  // after leaving and coming back).
  void reset(Vec2 centre, FloorState& state);

  // One physics substep ending with the centre at `centre`: the accumulator drains, or
  // refills inside a recharge zone. No allocation. Inline: the step loop calls it every
  // substep, mostly with the energy model off.
  void substep(Vec2 centre) noexcept {
    if (energy_on_) drain_or_recharge(centre);
  }

  // The end of a control step with the centre at `centre`. No allocation.
  void observe(Vec2 centre, FloorState& state) noexcept;

  [[nodiscard]] std::span<const Vec2> zone_centers() const noexcept { return zone_centers_; }
  [[nodiscard]] std::span<const Vec2> light_positions() const noexcept { return light_positions_; }
  [[nodiscard]] std::span<const PlacedLight> lights() const noexcept { return lights_; }
  // Whether `p` lies inside zone `zone` (at its position this epoch; boundary included).
  [[nodiscard]] bool in_zone(std::size_t zone, Vec2 p) const noexcept;
  // Whether `p` lies over a visible zone: what a ground sensor there reads.
  [[nodiscard]] bool visible_at(Vec2 p) const noexcept;
  [[nodiscard]] int sweep_columns() const noexcept { return sweep_cols_; }
  [[nodiscard]] int sweep_rows() const noexcept { return sweep_rows_; }

 private:
  // A zone at its position this epoch.
  struct ZoneGeom {
    bool circle = true;
    double cx = 0.0, cy = 0.0;
    double r2 = 0.0;            // circle: radius^2
    double hx = 0.0, hy = 0.0;  // half extents (circle: the radius)

    [[nodiscard]] bool contains(double x, double y) const noexcept {
      const double dx = x - cx;
      const double dy = y - cy;
      if (circle) return dx * dx + dy * dy <= r2;
      return std::abs(dx) <= hx && std::abs(dy) <= hy;
    }
  };

  void place_lights();
  void drain_or_recharge(Vec2 centre) noexcept;
  [[nodiscard]] bool in_recharge(double x, double y) const noexcept;
  // The state at `centre`; `fresh`: just placed (no rising edge, no new cell).
  void read(Vec2 centre, bool fresh, FloorState& state) noexcept;

  ArenaSpec arena_;
  std::vector<ZoneGeom> zones_;
  std::vector<Vec2> zone_centers_;
  std::uint32_t recharge_mask_ = 0;  // bit i: zone i recharges
  std::uint32_t visible_mask_ = 0;   // bit i: zone i is seen by the ground sensor
  std::vector<PlacedLight> lights_;
  std::vector<Vec2> light_positions_;
  double reach2_m2_ = 0.0;           // reach radius^2
  std::uint32_t inside_reach_ = 0;   // bit i: centre within reach of light i after the last step

  // Energy in integer units: full = discharge * recharge * substeps; each substep outside
  // a recharge zone takes recharge_steps units (discharge_steps * substeps substeps from
  // full to empty), each substep inside gives discharge_steps units.
  bool energy_on_ = false;
  std::int64_t energy_full_ = 1;
  std::int64_t energy_units_ = 1;
  std::int64_t energy_drain_ = 0;
  std::int64_t energy_gain_ = 0;

  // Area-sweeping grid, one bit per cell, sized here once.
  int sweep_cols_ = 1;
  int sweep_rows_ = 1;
  std::vector<std::uint64_t> visited_;
};

}  // namespace esc::sim
