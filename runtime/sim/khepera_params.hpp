#pragma once
// The simulated Khepera's constants, with their defaults and sources in
// docs/robot-model.md. Every field is settable from a script's `robot` block.
namespace esc::sim {

struct MotorParams {
  bool inertia = true;              // off: measured wheel speed equals the command at once
  double max_speed_mps = 0.08;      // command 1.0 (Khepera: about 8 mm/s per unit, +-10)
  double time_constant_s = 0.1;     // first-order lag of the wheel speed behind the command
  double max_accel_mps2 = 1.0;      // acceleration limit of each wheel
};

struct IrParams {
  double range_m = 0.05;            // reading is 0 at and beyond this distance
  double aperture_rad = 0.5236;     // total angle spanned by a sensor's rays (30 deg)
  int rays = 3;                     // rays per sensor, spread evenly over the aperture
  double noise_sd = 0.0;            // Gaussian noise on the normalised reading, then clamped to [0, 1]
};

struct KheperaParams {
  double body_radius_m = 0.0275;    // 55 mm diameter
  double body_height_m = 0.03;
  double mass_kg = 0.08;
  double wheel_base_m = 0.053;
  MotorParams motor;
  IrParams ir;
  double control_step_s = 0.1;      // one sense-control-act cycle
  int physics_substeps = 2;         // fixed physics steps per control step
};

}  // namespace esc::sim
