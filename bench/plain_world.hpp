#pragma once
// The plain reference's world: the paper's arena, IR and light sensors, motors and 2D
// motion written the simplest way, with no esc code, so that `esc bench` can say how close
// esc's step loop is to what the arithmetic alone costs (docs/performance.md, "Plain
// references"). The same model as esc's (docs/robot-model.md): walls and cylinders, eight
// IR sensors of `ir_rays` rays on Enki's response curve, ambient light with cosine
// incidence, first-order motor lag with an acceleration limit, the exact arc of a
// differential drive per substep, the energy accumulator in integer units. Not in it:
// Bullet (a contact here is a clearance test, and a body pushed into a wall is put back on
// its surface), the expression VM, the observable frame, boxes, noise.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace esc::bench::plain {

struct Circle {
  double x_m, y_m, r_m;
};

// Every number the plain loops use, copied from the experiment (bench/reference.cpp).
struct Setup {
  double width_m = 0.6, height_m = 0.6;
  std::vector<Circle> cylinders;
  double radius_m = 0.0275, wheel_base_m = 0.053;
  double max_speed_mps = 0.08, time_constant_s = 0.1, max_accel_mps2 = 1.0;
  double control_step_s = 0.1;
  int substeps = 2;
  double ir_range_m = 0.05, ir_aperture_rad = 0.5236;
  int ir_rays = 3;
  // The energy workloads: one light above one random recharge zone, the accumulator.
  double light_half_distance_m = 0.2, light_height_m = 0.05, zone_radius_m = 0.08;
  int discharge_steps = 285, recharge_steps = 100;
  int epochs = 10, steps = 150;
};

// The robot's state in the plane.
struct Robot {
  double x_m = 0, y_m = 0, heading_rad = 0;
  double left_mps = 0, right_mps = 0;   // measured wheel speeds
};

// The energy accumulator: integer units, drained every substep outside the recharge zone.
struct Accumulator {
  std::int64_t full, units, drain, gain;
  explicit Accumulator(const Setup& s)
      : full(std::int64_t{s.discharge_steps} * s.recharge_steps * s.substeps), units(full),
        drain(s.recharge_steps), gain(s.discharge_steps) {}
  void substep(bool recharging) {
    units = recharging ? std::min(full, units + gain) : std::max<std::int64_t>(0, units - drain);
  }
  [[nodiscard]] double level() const { return static_cast<double>(units) / static_cast<double>(full); }
};

class World {
 public:
  explicit World(const Setup& s);

  // A random pose clear of walls and cylinders by 5 mm, at rest.
  Robot random_start(std::mt19937_64& rng) const;
  // A zone centre keeping the zone inside the walls.
  void place_zone(std::mt19937_64& rng);

  // One control step: commands to target speeds, then `substeps` of motor lag and exact arc.
  // Returns true when the body touched a wall or cylinder. With an accumulator (the energy
  // workloads, which go on after a contact) a body pushed into a wall is put back on it, and
  // the accumulator drains or recharges every substep.
  bool step(Robot& r, double left_command, double right_command, Accumulator* energy) const;

  void read_ir(const Robot& r, double out[8]) const;
  void read_light(const Robot& r, double out[8]) const;
  [[nodiscard]] bool in_zone(const Robot& r) const;

  // The paper's per-step fitness term, max(forward speed, 0) * (1 - sqrt(wheel difference)),
  // from the motion over the step.
  [[nodiscard]] double forward_term(const Robot& before, const Robot& after) const;

  [[nodiscard]] const Setup& setup() const { return s_; }

 private:
  [[nodiscard]] double clearance(double x, double y) const;
  Setup s_;
  double decay_, max_delta_mps_, dt_s_;
  double curve_range_, curve_scale_;
  double mount_x_[8], mount_y_[8], face_x_[8], face_y_[8];
  std::vector<double> ray_x_, ray_y_, dir_x_, dir_y_;   // per ray, body frame
  double zone_x_ = 0.3, zone_y_ = 0.3;
};

}  // namespace esc::bench::plain
