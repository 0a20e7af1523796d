#pragma once
// A simulated robot's constants: the Khepera's by default, with their sources in
// docs/robot-model.md. Every field is settable from a script's `robot` block, so another
// differential-drive body (the e-puck, experiments/lib/epuck.esc) is data, not code.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

struct MotorParams {
  bool inertia = true;              // off: measured wheel speed equals the command at once
  double max_speed_mps = 0.08;      // command 1.0 (Khepera: about 8 mm/s per unit, +-10)
  double time_constant_s = 0.1;     // first-order lag of the wheel speed behind the command
  double max_accel_mps2 = 1.0;      // acceleration limit of each wheel
  // Speed error of each wheel, a fraction of its commanded speed (Gaussian sd, drawn per
  // wheel at each control step); 0: the wheels follow their commands exactly.
  double noise_sd = 0.0;
};

// Most IR sensors a robot carries: the observable frame holds as many `ir` slots.
inline constexpr int kMaxIrSensors = 8;

// Where an IR sensor sits on the body and where it looks, radians from the heading
// (positive = left). The light sensors are the same sensors in passive mode.
struct IrMount {
  double bearing_rad = 0.0;          // direction of the mount point from the body's centre
  double facing_rad = 0.0;           // direction of the sensor's axis
  std::optional<double> radius_m;    // distance of the mount point from the centre; none: on the rim
  friend bool operator==(const IrMount&, const IrMount&) = default;
};

// The Khepera's sensors (index 0..5 front, left to right; 6 back left; 7 back right), on
// its rim: mount and facing angles, degrees from the heading (docs/robot-model.md, "IR
// sensors"), and the mounts they make.
inline constexpr std::array<double, 8> kKheperaIrMountDeg = {68.0, 43.0, 13.0, -13.0, -43.0, -68.0, 158.0, -158.0};
inline constexpr std::array<double, 8> kKheperaIrFacingDeg = {90.0, 45.0, 10.0, -10.0, -45.0, -90.0, 180.0, 180.0};
[[nodiscard]] std::vector<IrMount> khepera_ir_mounts();

// A point of a measured response curve: the normalised reading at a distance.
struct IrResponsePoint {
  double distance_m = 0.0;
  double reading = 0.0;
  friend bool operator==(const IrResponsePoint&, const IrResponsePoint&) = default;
};

struct IrParams {
  double range_m = 0.05;            // reading is 0 at and beyond this distance
  double aperture_rad = 0.5236;     // total angle spanned by a sensor's rays (30 deg)
  int rays = 3;                     // rays per sensor, spread evenly over the aperture
  double noise_sd = 0.0;            // Gaussian noise on the normalised reading, then clamped to [0, 1]
  std::vector<IrMount> mounts = khepera_ir_mounts();   // at most kMaxIrSensors; `ir[i]` reads mounts[i]
  // The name scripts read the sensors by (`ir[i]`; the e-puck's `prox[i]`): the compiler's,
  // held with the sensors so that a robot declaration carries it.
  std::string name = "ir";
  // The response to an obstacle at distance x along a ray: Enki's curve
  //   F(x) = m (c - x0^2) / (x^2 - 2 x0 x + c)
  // rescaled to 1 at x = 0 and 0 at the range (m cancels), with Enki's constants for the
  // Khepera. Held in Enki's units, centimetres, so that the Khepera's curve is computed
  // from exactly the numbers it always was.
  double curve_x0_cm = -0.9;
  double curve_c_cm2 = 7.0;
  // A measured curve instead, when not empty: readings at increasing distances from 0,
  // linearly interpolated, 0 at and beyond the range.
  std::vector<IrResponsePoint> response;
};

// Ambient light: the same eight sensors in passive mode. A light of intensity I at distance
// d and incidence angle a (from the sensor's facing direction) adds
//   I * max(0, cos a) / (1 + (d / half_distance_m)^2)
// to a sensor's reading, unless a wall or obstacle is in the way; the sum is clamped to [0, 1].
struct LightSensorParams {
  double half_distance_m = 0.2;     // a unit light straight ahead at this distance reads 0.5
  double noise_sd = 0.0;            // Gaussian noise on the normalised reading, then clamped
};

// Light the robot gives off (a beacon on top, or its IR emitters as others' sensors see them
// in passive mode): a point source of `intensity` at its centre, `height_m` above the sensors'
// plane, which the other robots' light sensors read as they read an arena's light there (walls
// and obstacles shade it, robots do not). 0: none, the default.
struct EmissionParams {
  double intensity = 0.0;
  double height_m = 0.0;
};

// The accumulator of the homing experiment (paper section 4): full to empty in
// discharge_steps control steps outside recharge zones, empty to full in recharge_steps
// control steps inside one. Integrated exactly (integer units) at the physics substep rate.
struct EnergyParams {
  bool enabled = false;             // off: `energy` stays 1 and never ends an epoch
  int discharge_steps = 285;        // paper: "completely consumes the accumulator in 285 steps"
  int recharge_steps = 100;         // paper: "a full recharge takes 100 time steps"
};

// Ground sensors under the body (the Thymio II's two, `prox.ground`): each reads 1 where its
// point is over a visible zone (a dark mark on the floor, as the centre's `ground` does), 0
// elsewhere. None by default.
inline constexpr int kMaxGroundSensors = 4;

// A ground sensor's point: its direction from the body's centre (radians from the heading,
// positive = left) and its distance from it.
struct GroundMount {
  double bearing_rad = 0.0;
  double radius_m = 0.0;
  friend bool operator==(const GroundMount&, const GroundMount&) = default;
  // Its point in the body's frame.
  [[nodiscard]] Vec2 point() const noexcept { return polar(bearing_rad, radius_m); }
};

struct GroundSensorParams {
  std::vector<GroundMount> mounts;   // at most kMaxGroundSensors; `ground_sensor[i]` reads mounts[i]
  // The name scripts read them by (the Thymio's `prox_ground[i]`), as IrParams::name.
  std::string name = "ground_sensor";
};

// Bumpers: sectors of the body's edge, each reading 1 on a step in which the body touched a
// wall or obstacle at a bearing within it (from the heading, counter-clockwise from `from_rad`
// to `to_rad`, at most a full turn). None by default.
inline constexpr int kMaxBumpers = 4;

struct BumperSector {
  double from_rad = 0.0;
  double to_rad = 0.0;
  friend bool operator==(const BumperSector&, const BumperSector&) = default;
  // How much of the edge it covers, counter-clockwise from `from_rad` (validate.cpp bounds it).
  [[nodiscard]] double width_rad() const noexcept { return to_rad - from_rad; }
  // Whether bearing `b` (radians from the heading) lies in the sector.
  [[nodiscard]] bool holds(double b) const noexcept;
};

// Lehman & Stanley's (2011) maze navigator's sensors, on the Khepera (docs/robot-model.md,
// "Rangefinders" and "Goal radars"). Neither is read unless declared: none by default.
// Most rangefinders and radar slices: the observable frame holds as many `range` and
// `radar` slots (runtime/expr/observables.hpp).
inline constexpr int kMaxRangefinders = 8;
inline constexpr int kMaxRadars = 8;

// Rays from the body's centre at these angles from the heading (positive = left), reading
// the distance to the nearest wall or obstacle along the ray over range_m, 1 when none is
// within range_m. Their default range is the navigator's, 100 units for a body radius of 8,
// scaled to the Khepera's radius: 12.5 x 27.5 mm.
struct RangefinderParams {
  std::vector<double> angles_rad;   // at most kMaxRangefinders; empty: no rangefinders
  double range_m = 0.34375;
};

// How the robot moves. Differential: two wheels behind motors (motor.hpp, drive.hpp), the
// body dynamic in Bullet. Acceleration: Lehman & Stanley's maze navigator (their maze.h): the
// first command accelerates the turn rate and the second the forward speed, each clamped to
// its top; the body moves kinematically, and a move that would bring its centre within its
// radius of a wall or obstacle is cancelled (the speeds kept), with no contact solver.
enum class DriveKind { Differential, Acceleration };

// The acceleration drive's turning; its forward speed is motor.max_speed_mps at most and
// changes by motor.max_accel_mps2 at command 1. The navigator's: 3 degrees a step at most,
// (output - 0.5) degrees a step per step, a step being a control step.
struct TurnParams {
  double max_rate_radps = 0.5235987755982988;       // 30 deg/s: 3 deg per 100 ms step
  double max_accel_radps2 = 0.8726646259971648;     // 50 deg/s^2: command 1 adds 0.5 deg per step per step
};

// Most vertices a body's outline holds.
inline constexpr int kMaxOutlineVertices = 32;

struct RobotParams {
  DriveKind drive = DriveKind::Differential;
  TurnParams turn;                  // the acceleration drive's
  double body_radius_m = 0.0275;    // 55 mm diameter; with an outline, the circle around it
  // A convex outline instead of the disc (outline.hpp): its vertices in the body's frame (x
  // along the heading, y to the left, from the point the wheels turn about), in order round
  // it; empty: the disc. The Thymio II's reaches 8 cm ahead of its axle and 3 cm behind.
  std::vector<Vec2> outline;
  double body_height_m = 0.03;
  double mass_kg = 0.08;
  double wheel_base_m = 0.053;
  MotorParams motor;
  IrParams ir;
  double control_step_s = 0.1;      // one sense-control-act cycle
  int physics_substeps = 2;         // fixed physics steps per control step
  LightSensorParams light;
  EmissionParams emission;
  EnergyParams energy;
  RangefinderParams rangefinders;
  GroundSensorParams ground;
  std::vector<BumperSector> bumpers;   // at most kMaxBumpers; `bumper[i]` reads bumpers[i]
  // Pie-slice goal radars: the circle around the body split into this many equal slices,
  // slice 0 centred on the heading, then counter-clockwise; 0: none. 4 are the navigator's
  // front, left, back and right.
  int radars = 0;
};

}  // namespace esc::sim
