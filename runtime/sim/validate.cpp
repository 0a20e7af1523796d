#include "runtime/sim/validate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "runtime/sim/outline.hpp"

namespace esc::sim {

namespace {

using D = Dimension;
using O = Object;
using R = Relation;

// Rounding in a script's units (60cm is 0.6000000000000001 m) never puts a part outside.
constexpr double kInsideTolerance_m = 1e-9;

constexpr std::string_view kContactAlso[] = {"max_speed", "control_step", "body_radius", "wheel_base"};
constexpr std::string_view kSweepAlso[] = {"size"};
constexpr std::string_view kWheelBaseAlso[] = {"body_radius"};
constexpr std::string_view kIrMountAlso[] = {"body_radius"};
constexpr std::string_view kNoiseAlso[] = {"drive"};
constexpr std::string_view kIrCurveAlso[] = {"ir_curve_x0"};
constexpr std::string_view kFitAlso[] = {"body_radius"};
constexpr std::string_view kOutlineRadiusAlso[] = {"body_radius"};
constexpr std::string_view kOutlineGroundAlso[] = {"body_outline"};
// Sharper corners and thinner bodies than these leave Bullet's hull short of the outline
// (body.cpp builds it from the outline moved in by its 0.5 mm margin).
constexpr double kMinOutlineCorner_rad = 30 * std::numbers::pi / 180;
constexpr double kOutlineInset_m = 0.001;

constexpr std::string_view kInside = "positions are measured from the arena's lower-left inner corner";
constexpr std::string_view kStartClear = "a body placed inside a wall or an obstacle is pushed out by the solver";

// In the order of `Rule` (checked by a static_assert below).
constexpr RuleInfo kRules[] = {
    {Rule::ArenaWidth, O::Arena, "size", {}, R::Above, D::Length, "arena.width_m", "an arena has an inside"},
    {Rule::ArenaHeight, O::Arena, "size", {}, R::Above, D::Length, "arena.height_m", "an arena has an inside"},
    {Rule::ObstacleCount, O::Arena, "block", {}, R::AtMost, D::Count, "arena obstacle count",
     "Bullet's broadphase indexes objects with 16-bit handles"},
    {Rule::BlockSize, O::Arena, "block", {}, R::Above, D::Length, "arena.boxes[{}].size_m", "a block has a body"},
    {Rule::BlockInside, O::Arena, "block", {}, R::AtMost, D::Length, "arena.boxes[{}] beyond the walls", kInside},
    {Rule::CylinderRadius, O::Arena, "cylinder", {}, R::Above, D::Length, "arena.cylinders[{}].radius_m",
     "a cylinder has a body"},
    {Rule::CylinderInside, O::Arena, "cylinder", {}, R::AtMost, D::Length, "arena.cylinders[{}] beyond the walls",
     kInside},
    {Rule::WallLength, O::Arena, "wall", {}, R::Above, D::Length, "arena.walls[{}] length", "a wall has a length"},
    {Rule::WallThickness, O::Arena, "wall", {}, R::Above, D::Length, "arena.walls[{}].thickness_m",
     "a wall has a body"},
    {Rule::WallInside, O::Arena, "wall", {}, R::AtMost, D::Length, "arena.walls[{}] beyond the walls", kInside},
    {Rule::StartInside, O::Arena, "start", {}, R::AtMost, D::Length, "arena.fixed_start beyond the walls", kInside},
    {Rule::GoalInside, O::Arena, "goal", {}, R::AtMost, D::Length, "arena.goal beyond the walls", kInside},
    {Rule::ZoneCount, O::Arena, "zone", {}, R::AtMost, D::Count, "arena zone count",
     "the observable frame holds one `in(zone)` slot per zone"},
    {Rule::ZoneRadius, O::Arena, "zone", {}, R::Above, D::Length, "arena.zones[{}].radius_m", "a zone has an area"},
    {Rule::ZoneSize, O::Arena, "zone", {}, R::Above, D::Length, "arena.zones[{}].size_m", "a zone has an area"},
    {Rule::ZoneInside, O::Arena, "zone", {}, R::AtMost, D::Length, "arena.zones[{}] beyond the walls", kInside},
    {Rule::ZoneFits, O::Arena, "zone", {}, R::AtMost, D::Length, "arena.zones[{}] larger than the arena",
     "a zone placed at random lies inside the arena"},
    {Rule::LightCount, O::Arena, "light", {}, R::AtMost, D::Count, "arena light count",
     "the observable frame holds one `reached(light)` slot per light"},
    {Rule::LightHeight, O::Arena, "light", {}, R::AtLeast, D::Length, "arena.lights[{}].height_m",
     "a light stands at or above the sensors' plane"},
    {Rule::LightIntensity, O::Arena, "light", {}, R::AtLeast, D::Number, "arena.lights[{}].intensity",
     "a light adds to the readings"},
    {Rule::LightZone, O::Arena, "light", {}, R::AtMost, D::Count, "arena.lights[{}].above_zone",
     "a light stands above a zone of its arena (-1: a fixed light)"},
    {Rule::LightInside, O::Arena, "light", {}, R::AtMost, D::Length, "arena.lights[{}].position_m beyond the walls",
     kInside},
    {Rule::SweepCell, O::Arena, "sweep_cell", {}, R::Above, D::Length, "arena.sweep_cell_m",
     "the area-sweeping grid has cells"},
    {Rule::SweepGrid, O::Arena, "sweep_cell", kSweepAlso, R::AtMost, D::Count, "arena.sweep_cell_m: sweep grid cells",
     "the area-sweeping grid keeps one bit per cell for every robot"},
    {Rule::ReachRadius, O::Arena, "reach_radius", {}, R::Above, D::Length, "arena.reach_radius_m",
     "`reached(light)` needs a distance"},
    {Rule::RobotFits, O::Placement, "size", kFitAlso, R::Above, D::Length, "arena side against the robot's diameter",
     "the robot must fit between the walls"},
    {Rule::StartClearOfWalls, O::Placement, "start", kFitAlso, R::AtLeast, D::Length,
     "arena.fixed_start distance to a wall", kStartClear},
    {Rule::StartClearOfCylinder, O::Placement, "start", kFitAlso, R::AtLeast, D::Length,
     "arena.fixed_start distance to arena.cylinders[{}]", kStartClear},
    {Rule::StartClearOfBlock, O::Placement, "start", kFitAlso, R::AtLeast, D::Length,
     "arena.fixed_start distance to arena.boxes[{}]", kStartClear},
    {Rule::StartClearOfWall, O::Placement, "start", kFitAlso, R::AtLeast, D::Length,
     "arena.fixed_start distance to arena.walls[{}]", kStartClear},
    {Rule::BodyRadius, O::Robot, "body_radius", {}, R::Above, D::Length, "robot.body_radius_m", "a body has a size"},
    {Rule::BodyHeight, O::Robot, "body_height", {}, R::Above, D::Length, "robot.body_height_m", "a body has a size"},
    {Rule::Mass, O::Robot, "mass", {}, R::Above, D::Mass, "robot.mass_kg", "a body has a mass"},
    {Rule::WheelBase, O::Robot, "wheel_base", {}, R::Above, D::Length, "robot.wheel_base_m",
     "the wheels are apart"},
    {Rule::WheelBaseWithinBody, O::Robot, "wheel_base", kWheelBaseAlso, R::AtMost, D::Length,
     "robot.wheel_base_m against the body's diameter", "the wheels are under the body"},
    {Rule::MaxSpeed, O::Robot, "max_speed", {}, R::Above, D::Speed, "robot.motor.max_speed_mps",
     "command 1.0 drives forward"},
    {Rule::TimeConstant, O::Robot, "time_constant", {}, R::AtLeast, D::Time, "robot.motor.time_constant_s",
     "a lag is never negative"},
    {Rule::MaxAccel, O::Robot, "max_accel", {}, R::Above, D::Acceleration, "robot.motor.max_accel_mps2",
     "the wheels can speed up"},
    {Rule::MotorNoise, O::Robot, "motor_noise", {}, R::AtLeast, D::Number, "robot.motor.noise_sd",
     "a standard deviation is never negative"},
    {Rule::IrRange, O::Robot, "ir_range", {}, R::Above, D::Length, "robot.ir.range_m", "a sensor sees some distance"},
    {Rule::IrApertureMin, O::Robot, "ir_aperture", {}, R::AtLeast, D::Angle, "robot.ir.aperture_rad",
     "an aperture is never negative"},
    {Rule::IrApertureMax, O::Robot, "ir_aperture", {}, R::Below, D::Angle, "robot.ir.aperture_rad",
     "a sensor's rays point forward of the sensor"},
    {Rule::IrRaysMin, O::Robot, "ir_rays", {}, R::AtLeast, D::Count, "robot.ir.rays", "a sensor casts a ray"},
    {Rule::IrRaysMax, O::Robot, "ir_rays", {}, R::AtMost, D::Count, "robot.ir.rays",
     "the IR model holds at most 64 rays per sensor"},
    {Rule::IrNoise, O::Robot, "ir_noise", {}, R::AtLeast, D::Number, "robot.ir.noise_sd",
     "a standard deviation is never negative"},
    {Rule::IrCount, O::Robot, "ir_sensors", {}, R::AtMost, D::Count, "robot.ir.mounts count",
     "the observable frame holds 8 `ir` slots"},
    {Rule::IrMountRadiusMin, O::Robot, "ir_sensors", {}, R::AtLeast, D::Length, "robot.ir.mounts[{}].radius_m",
     "a sensor sits on the body"},
    {Rule::IrMountRadiusMax, O::Robot, "ir_sensors", kIrMountAlso, R::AtMost, D::Length,
     "robot.ir.mounts[{}].radius_m against the body's radius", "a sensor sits on the body"},
    {Rule::IrCurve, O::Robot, "ir_curve_c", kIrCurveAlso, R::Above, D::Number,
     "robot.ir.curve_c_cm2 - curve_x0_cm^2 (cm^2)", "Enki's curve has no pole (c above x0^2)"},
    {Rule::IrResponseCount, O::Robot, "ir_response", {}, R::AtMost, D::Count, "robot.ir.response count",
     "a measured response holds at most 64 points"},
    {Rule::IrResponseStart, O::Robot, "ir_response", {}, R::AtLeast, D::Length, "robot.ir.response[{}].distance_m",
     "a distance is never negative"},
    {Rule::IrResponseDistance, O::Robot, "ir_response", {}, R::Above, D::Length,
     "robot.ir.response[{}].distance_m against the point before it", "a response's distances increase"},
    {Rule::IrResponseReadingMin, O::Robot, "ir_response", {}, R::AtLeast, D::Number,
     "robot.ir.response[{}].reading", "readings are normalised, 0 .. 1"},
    {Rule::IrResponseReadingMax, O::Robot, "ir_response", {}, R::AtMost, D::Number,
     "robot.ir.response[{}].reading", "readings are normalised, 0 .. 1"},
    {Rule::ControlStep, O::Robot, "control_step", {}, R::Above, D::Time, "robot.control_step_s",
     "time advances at every step"},
    {Rule::SubstepsMin, O::Robot, "substeps", {}, R::AtLeast, D::Count, "robot.physics_substeps",
     "physics advances at every control step"},
    {Rule::SubstepsMax, O::Robot, "substeps", {}, R::AtMost, D::Count, "robot.physics_substeps",
     "a control step stays a bounded amount of work"},
    {Rule::LightHalfDistance, O::Robot, "light_half_distance", {}, R::Above, D::Length,
     "robot.light.half_distance_m", "light fades with distance"},
    {Rule::LightNoise, O::Robot, "light_noise", {}, R::AtLeast, D::Number, "robot.light.noise_sd",
     "a standard deviation is never negative"},
    {Rule::EnergyDischargeMin, O::Robot, "energy_discharge", {}, R::AtLeast, D::Count,
     "robot.energy.discharge_steps", "the accumulator takes a step to empty"},
    {Rule::EnergyDischargeMax, O::Robot, "energy_discharge", {}, R::AtMost, D::Count,
     "robot.energy.discharge_steps", "the accumulator counts in 64-bit integer units"},
    {Rule::EnergyRechargeMin, O::Robot, "energy_recharge", {}, R::AtLeast, D::Count, "robot.energy.recharge_steps",
     "the accumulator takes a step to fill"},
    {Rule::EnergyRechargeMax, O::Robot, "energy_recharge", {}, R::AtMost, D::Count, "robot.energy.recharge_steps",
     "the accumulator counts in 64-bit integer units"},
    {Rule::RangefinderCount, O::Robot, "rangefinders", {}, R::AtMost, D::Count, "robot.rangefinders.angles_rad count",
     "the observable frame holds 8 `range` slots"},
    {Rule::RangefinderRange, O::Robot, "rangefinder_range", {}, R::Above, D::Length, "robot.rangefinders.range_m",
     "a rangefinder sees some distance"},
    {Rule::RadarsMin, O::Robot, "radars", {}, R::AtLeast, D::Count, "robot.radars", "a count is never negative"},
    {Rule::RadarsMax, O::Robot, "radars", {}, R::AtMost, D::Count, "robot.radars",
     "the observable frame holds 8 `radar` slots"},
    {Rule::ContactLookAhead, O::Robot, "substeps", kContactAlso, R::AtMost, D::Length,
     "robot.physics_substeps: travel of the body's rim per substep",
     "the contact solver sees walls only 10 mm ahead of the moving body"},
    {Rule::TurnRate, O::Robot, "max_turn_rate", {}, R::Above, D::TurnRate, "robot.turn.max_rate_radps",
     "the acceleration drive can turn"},
    {Rule::TurnAccel, O::Robot, "max_turn_accel", {}, R::Above, D::TurnAcceleration, "robot.turn.max_accel_radps2",
     "the acceleration drive's turn rate can change"},
    {Rule::NoiseWithoutWheels, O::Robot, "motor_noise", kNoiseAlso, R::AtMost, D::Number,
     "robot.motor.noise_sd under the acceleration drive", "motor noise is an error of each wheel's speed"},
    {Rule::OutlineCountMin, O::Robot, "body_outline", {}, R::AtLeast, D::Count, "robot.outline vertex count",
     "an outline encloses an area"},
    {Rule::OutlineCountMax, O::Robot, "body_outline", {}, R::AtMost, D::Count, "robot.outline vertex count",
     "an outline holds at most 32 vertices"},
    {Rule::OutlineConvex, O::Robot, "body_outline", {}, R::Above, D::Number,
     "robot.outline[{}]: the sine of its turn there", "an outline is convex, its vertices in order round it"},
    {Rule::OutlineAroundCentre, O::Robot, "body_outline", {}, R::Above, D::Length,
     "robot.outline: the depth of its origin inside it", "the point the wheels turn about lies inside the body"},
    {Rule::OutlineWithinRadius, O::Robot, "body_outline", kOutlineRadiusAlso, R::AtMost, D::Length,
     "robot.outline[{}] distance from the centre against body_radius",
     "body_radius is the circle around the outline, which placement and the sensors' reach use"},
    {Rule::OutlineWithoutWheels, O::Robot, "body_outline", kNoiseAlso, R::AtMost, D::Count,
     "robot.outline vertex count under the acceleration drive",
     "the acceleration drive moves a disc (a move that brings its rim to a wall is cancelled)"},
    {Rule::GroundCount, O::Robot, "ground_sensors", {}, R::AtMost, D::Count, "robot.ground.mounts count",
     "the observable frame holds 4 `ground_sensor` slots"},
    {Rule::GroundMountRadiusMin, O::Robot, "ground_sensors", {}, R::AtLeast, D::Length,
     "robot.ground.mounts[{}].radius_m", "a sensor sits under the body"},
    {Rule::GroundMountRadiusMax, O::Robot, "ground_sensors", kIrMountAlso, R::AtMost, D::Length,
     "robot.ground.mounts[{}].radius_m against the body's radius", "a sensor sits under the body"},
    {Rule::BumperCount, O::Robot, "bumpers", {}, R::AtMost, D::Count, "robot.bumpers count",
     "the observable frame holds 4 `bumper` slots"},
    {Rule::BumperSectorMin, O::Robot, "bumpers", {}, R::Above, D::Angle, "robot.bumpers[{}] width",
     "a bumper covers some of the body's edge, counter-clockwise from its first angle to its second"},
    {Rule::BumperSectorMax, O::Robot, "bumpers", {}, R::AtMost, D::Angle, "robot.bumpers[{}] width",
     "a bumper covers at most the body's whole edge"},
    {Rule::OutlineCorner, O::Robot, "body_outline", {}, R::AtLeast, D::Angle, "robot.outline[{}] corner",
     "Bullet rounds a corner by its 0.5 mm margin: a sharper one's hull falls short of the outline by over 1.4 mm"},
    {Rule::OutlineThin, O::Robot, "body_outline", {}, R::Above, D::Length,
     "robot.outline moved in by 1 mm: its narrowest depth", "Bullet's hull is the outline moved in by its 0.5 mm margin"},
    {Rule::GroundUnderOutline, O::Robot, "ground_sensors", kOutlineGroundAlso, R::AtLeast, D::Length,
     "robot.ground.mounts[{}] depth inside the outline", "a sensor sits under the body"},
    {Rule::EmissionIntensity, O::Robot, "emission", {}, R::AtLeast, D::Number, "robot.emission.intensity",
     "a light gives off no negative light"},
    {Rule::EmissionHeight, O::Robot, "emission_height", {}, R::AtLeast, D::Length, "robot.emission.height_m",
     "the source is at or above the sensors' plane"},
};

constexpr bool in_rule_order() {
  for (std::size_t i = 0; i < std::size(kRules); ++i)
    if (static_cast<std::size_t>(kRules[i].rule) != i) return false;
  return true;
}
static_assert(in_rule_order(), "kRules must list every Rule in the order of the enum");
static_assert(static_cast<std::size_t>(Rule::EmissionHeight) + 1 == std::size(kRules));

// True when `found` relates to `limit` as `rel` demands; NaN never does.
bool holds(Relation rel, double found, double limit) {
  switch (rel) {
    case R::Above: return found > limit && std::isfinite(found);
    case R::AtLeast: return found >= limit && std::isfinite(found);
    case R::Below: return found < limit;
    case R::AtMost: return found <= limit;
  }
  return false;
}

class Checker {
 public:
  explicit Checker(std::vector<Problem>& out) : out_(out) {}

  // Records a problem unless `found` relates to `limit` as the rule demands; true when it does.
  bool require(Rule rule, double found, double limit, int index = -1) {
    if (holds(rule_info(rule).relation, found, limit)) return true;
    fail(rule, found, limit, index);
    return false;
  }
  void fail(Rule rule, double found, double limit, int index) { out_.push_back(Problem{rule, index, found, limit}); }
  // At most `max` parts: the problem is about the first one too many.
  bool at_most(Rule rule, std::size_t count, std::size_t max) {
    return require(rule, static_cast<double>(count), static_cast<double>(max), static_cast<int>(max));
  }
  // "Lies inside": `beyond` is how far a part reaches past the walls (NaN fails too).
  bool inside(Rule rule, double beyond, int index) {
    if (beyond <= kInsideTolerance_m) return true;
    fail(rule, beyond, 0.0, index);
    return false;
  }

 private:
  std::vector<Problem>& out_;
};

// How far the axis-aligned extent [lo_x, hi_x] x [lo_y, hi_y] reaches past the walls (<= 0 inside).
double beyond(const ArenaSpec& a, double lo_x, double hi_x, double lo_y, double hi_y) {
  return std::max({-lo_x, hi_x - a.width_m, -lo_y, hi_y - a.height_m});
}

std::array<Vec2, 4> corners(const BoxObstacle& b) {
  const double c = std::cos(b.angle_rad), s = std::sin(b.angle_rad);
  const double hx = b.size_m.x / 2, hy = b.size_m.y / 2;
  const std::array<Vec2, 4> d = {{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}};
  std::array<Vec2, 4> k;
  for (std::size_t i = 0; i < 4; ++i)
    k[i] = {b.center_m.x + c * d[i].x - s * d[i].y, b.center_m.y + s * d[i].x + c * d[i].y};
  return k;
}

// How far a rotated box reaches past the walls (NaN when it is not finite).
double box_beyond(const ArenaSpec& a, const BoxObstacle& b) {
  if (!std::isfinite(b.angle_rad + b.center_m.x + b.center_m.y)) return std::numeric_limits<double>::quiet_NaN();
  double reach = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : corners(b)) reach = std::max(reach, beyond(a, p.x, p.x, p.y, p.y));
  return reach;
}

// Distance from a point to a rotated box (0 inside).
double distance_to_box(const BoxObstacle& b, double px, double py) {
  const double c = std::cos(-b.angle_rad), s = std::sin(-b.angle_rad);
  const double dx = px - b.center_m.x, dy = py - b.center_m.y;
  const double lx = c * dx - s * dy, ly = s * dx + c * dy;
  return std::hypot(std::max(std::abs(lx) - b.size_m.x / 2, 0.0), std::max(std::abs(ly) - b.size_m.y / 2, 0.0));
}

void check_obstacles(const ArenaSpec& a, bool sized, Checker& c) {
  const std::size_t obstacles = a.boxes.size() + a.cylinders.size() + a.walls.size();
  c.at_most(Rule::ObstacleCount, obstacles, kMaxObstacles);
  for (std::size_t i = 0; i < a.boxes.size(); ++i) {
    const BoxObstacle& b = a.boxes[i];
    const int at = static_cast<int>(i);
    if (!c.require(Rule::BlockSize, std::min(b.size_m.x, b.size_m.y), 0.0, at) || !sized) continue;
    c.inside(Rule::BlockInside, box_beyond(a, b), at);
  }
  for (std::size_t i = 0; i < a.cylinders.size(); ++i) {
    const CylinderObstacle& k = a.cylinders[i];
    const int at = static_cast<int>(i);
    if (!c.require(Rule::CylinderRadius, k.radius_m, 0.0, at) || !sized) continue;
    c.inside(Rule::CylinderInside,
             beyond(a, k.center_m.x - k.radius_m, k.center_m.x + k.radius_m, k.center_m.y - k.radius_m,
                    k.center_m.y + k.radius_m),
             at);
  }
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    const BoxObstacle b = wall_box(a.walls[i]);
    const int at = static_cast<int>(i);
    const bool body = c.require(Rule::WallLength, b.size_m.x, 0.0, at);
    if (c.require(Rule::WallThickness, b.size_m.y, 0.0, at) && body && sized)
      c.inside(Rule::WallInside, box_beyond(a, b), at);
  }
}

void check_zones(const ArenaSpec& a, bool sized, Checker& c) {
  c.at_most(Rule::ZoneCount, a.zones.size(), kMaxZones);
  for (std::size_t i = 0; i < a.zones.size(); ++i) {
    const Zone& z = a.zones[i];
    const int at = static_cast<int>(i);
    const bool circle = z.shape == ZoneShape::Circle;
    const double hx = circle ? z.radius_m : z.size_m.x / 2, hy = circle ? z.radius_m : z.size_m.y / 2;
    if (!(circle ? c.require(Rule::ZoneRadius, z.radius_m, 0.0, at)
                 : c.require(Rule::ZoneSize, std::min(z.size_m.x, z.size_m.y), 0.0, at)) ||
        !sized)
      continue;
    if (z.random_position)
      c.inside(Rule::ZoneFits, std::max(2 * hx - a.width_m, 2 * hy - a.height_m), at);
    else
      c.inside(Rule::ZoneInside, beyond(a, z.center_m.x - hx, z.center_m.x + hx, z.center_m.y - hy, z.center_m.y + hy),
               at);
  }
}

void check_lights(const ArenaSpec& a, bool sized, Checker& c) {
  c.at_most(Rule::LightCount, a.lights.size(), kMaxLights);
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    const LightSource& l = a.lights[i];
    const int at = static_cast<int>(i);
    c.require(Rule::LightHeight, l.height_m, 0.0, at);
    c.require(Rule::LightIntensity, l.intensity, 0.0, at);
    if (l.above_zone < -1 || l.above_zone >= static_cast<int>(a.zones.size()))
      c.fail(Rule::LightZone, l.above_zone, static_cast<double>(a.zones.size()) - 1, at);
    if (l.above_zone == -1 && sized)
      c.inside(Rule::LightInside, beyond(a, l.position_m.x, l.position_m.x, l.position_m.y, l.position_m.y), at);
  }
}

// A sensor's distance from the centre: never negative, and within the body's circle when the
// body is valid. True when both hold as far as checked.
bool check_mount_radius(Rule min, Rule max, double r, const RobotParams& robot, bool body, int at, Checker& c) {
  return c.require(min, r, 0.0, at) && (!body || c.require(max, r, robot.body_radius_m, at));
}

// The mounts sit on the body; Enki's curve has no pole; a measured response's distances
// increase from 0 and its readings are normalised.
void check_ir_layout(const RobotParams& robot, bool body, Checker& c) {
  const IrParams& ir = robot.ir;
  c.at_most(Rule::IrCount, ir.mounts.size(), kMaxIrSensors);
  for (std::size_t i = 0; i < ir.mounts.size(); ++i)
    if (ir.mounts[i].radius_m)
      check_mount_radius(Rule::IrMountRadiusMin, Rule::IrMountRadiusMax, *ir.mounts[i].radius_m, robot, body,
                         static_cast<int>(i), c);
  if (ir.response.empty()) {
    c.require(Rule::IrCurve, ir.curve_c_cm2 - ir.curve_x0_cm * ir.curve_x0_cm, 0.0);
    return;
  }
  c.at_most(Rule::IrResponseCount, ir.response.size(), kMaxIrResponsePoints);
  for (std::size_t i = 0; i < ir.response.size(); ++i) {
    const IrResponsePoint& p = ir.response[i];
    const int at = static_cast<int>(i);
    if (i == 0) c.require(Rule::IrResponseStart, p.distance_m, 0.0, at);
    else c.require(Rule::IrResponseDistance, p.distance_m, ir.response[i - 1].distance_m, at);
    if (c.require(Rule::IrResponseReadingMin, p.reading, 0.0, at)) c.require(Rule::IrResponseReadingMax, p.reading, 1.0, at);
  }
}

// A convex outline round the centre, inside the body's circle; none under the acceleration
// drive. True when the robot has one and it holds (what its ground sensors are checked against).
bool check_outline(const RobotParams& robot, bool body, Checker& c) {
  const std::vector<Vec2>& outline = robot.outline;
  if (outline.empty()) return false;
  if (robot.drive == DriveKind::Acceleration) {
    c.require(Rule::OutlineWithoutWheels, static_cast<double>(outline.size()), 0.0);
    return false;
  }
  if (!c.require(Rule::OutlineCountMin, static_cast<double>(outline.size()), 3.0)) return false;
  bool ok = c.at_most(Rule::OutlineCountMax, outline.size(), kMaxOutlineVertices);
  int at = -1;
  const double turn = smallest_turn(outline, at);
  if (!c.require(Rule::OutlineConvex, turn, 0.0, at)) return false;
  const std::vector<Vec2> ccw = counter_clockwise(outline);
  if (!c.require(Rule::OutlineCorner, smallest_corner(ccw, at), kMinOutlineCorner_rad, at)) return false;
  // Moved in, a body thinner than twice the inset turns inside out.
  const std::vector<Vec2> in = inset(ccw, kOutlineInset_m);
  int unused = -1;
  const bool kept = twice_signed_area(in) > 0.0 && smallest_turn(in, unused) > 0.0;
  if (!c.require(Rule::OutlineThin, kept ? 1.0 : 0.0, 0.0)) return false;
  ok = c.require(Rule::OutlineAroundCentre, origin_depth(ccw), 0.0) && ok;
  if (!body) return false;
  for (std::size_t i = 0; i < outline.size(); ++i)
    ok = c.require(Rule::OutlineWithinRadius, std::hypot(outline[i].x, outline[i].y),
                   robot.body_radius_m + kInsideTolerance_m, static_cast<int>(i)) &&
         ok;
  return ok;
}

// At most kMaxGroundSensors, each on the body: within its circle and, with an outline that
// holds, under it.
void check_ground(const RobotParams& robot, bool body, bool outline, Checker& c) {
  c.at_most(Rule::GroundCount, robot.ground.mounts.size(), kMaxGroundSensors);
  const std::vector<Vec2> ccw = outline ? counter_clockwise(robot.outline) : std::vector<Vec2>{};
  for (std::size_t i = 0; i < robot.ground.mounts.size(); ++i) {
    const GroundMount& m = robot.ground.mounts[i];
    const int at = static_cast<int>(i);
    if (check_mount_radius(Rule::GroundMountRadiusMin, Rule::GroundMountRadiusMax, m.radius_m, robot, body, at, c) &&
        outline)
      c.require(Rule::GroundUnderOutline, origin_depth(ccw, m.point()), 0.0, at);
  }
}

[[noreturn]] void throw_first(const std::vector<Problem>& problems) {
  throw std::invalid_argument(problems.front().message());
}

}  // namespace

std::span<const RuleInfo> rules() noexcept { return kRules; }

const RuleInfo& rule_info(Rule r) noexcept { return kRules[static_cast<std::size_t>(r)]; }

std::string_view relation_words(Relation r) noexcept {
  switch (r) {
    case R::Above: return "above";
    case R::AtLeast: return "at least";
    case R::Below: return "below";
    case R::AtMost: return "at most";
  }
  return "";
}

const RuleInfo& Problem::info() const noexcept { return rule_info(rule); }

std::string Problem::message() const {
  const RuleInfo& r = info();
  std::string field(r.field);
  if (const std::size_t at = field.find("{}"); at != std::string::npos) field.replace(at, 2, std::to_string(index));
  std::ostringstream msg;
  msg << field << " must be " << relation_words(r.relation) << ' ' << limit << " (got " << found << "): " << r.why;
  return msg.str();
}

std::vector<Problem> arena_problems(const ArenaSpec& a) {
  std::vector<Problem> out;
  Checker c(out);
  const bool wide = c.require(Rule::ArenaWidth, a.width_m, 0.0);
  const bool sized = c.require(Rule::ArenaHeight, a.height_m, 0.0) && wide;
  check_obstacles(a, sized, c);
  if (a.fixed_start && sized) {
    const Pose& p = *a.fixed_start;
    const double reach = std::isfinite(p.heading_rad) ? beyond(a, p.x_m, p.x_m, p.y_m, p.y_m)
                                                      : std::numeric_limits<double>::quiet_NaN();
    c.inside(Rule::StartInside, reach, -1);
  }
  if (a.goal && sized) c.inside(Rule::GoalInside, beyond(a, a.goal->x, a.goal->x, a.goal->y, a.goal->y), -1);
  check_zones(a, sized, c);
  check_lights(a, sized, c);
  if (c.require(Rule::SweepCell, a.sweep_cell_m, 0.0) && sized) {
    const double cells = std::ceil(a.width_m / a.sweep_cell_m) * std::ceil(a.height_m / a.sweep_cell_m);
    c.require(Rule::SweepGrid, cells, kMaxSweepCells);
  }
  c.require(Rule::ReachRadius, a.reach_radius_m, 0.0);
  return out;
}

std::vector<Problem> placement_problems(const ArenaSpec& a, const RobotParams& robot) {
  std::vector<Problem> out;
  Checker c(out);
  const double r = robot.body_radius_m;
  if (!c.require(Rule::RobotFits, std::min(a.width_m, a.height_m), 2 * r) || !a.fixed_start) return out;
  const Pose& p = *a.fixed_start;
  if (!c.require(Rule::StartClearOfWalls, std::min({p.x_m, p.y_m, a.width_m - p.x_m, a.height_m - p.y_m}), r))
    return out;
  for (std::size_t i = 0; i < a.cylinders.size(); ++i) {
    const CylinderObstacle& k = a.cylinders[i];
    if (!c.require(Rule::StartClearOfCylinder,
                   std::hypot(p.x_m - k.center_m.x, p.y_m - k.center_m.y) - k.radius_m, r, static_cast<int>(i)))
      return out;
  }
  for (std::size_t i = 0; i < a.boxes.size(); ++i)
    if (!c.require(Rule::StartClearOfBlock, distance_to_box(a.boxes[i], p.x_m, p.y_m), r, static_cast<int>(i)))
      return out;
  for (std::size_t i = 0; i < a.walls.size(); ++i)
    if (!c.require(Rule::StartClearOfWall, distance_to_box(wall_box(a.walls[i]), p.x_m, p.y_m), r,
                   static_cast<int>(i)))
      return out;
  return out;
}

std::vector<Problem> robot_problems(const RobotParams& robot) {
  std::vector<Problem> out;
  Checker c(out);
  const bool body = c.require(Rule::BodyRadius, robot.body_radius_m, 0.0);
  c.require(Rule::BodyHeight, robot.body_height_m, 0.0);
  c.require(Rule::Mass, robot.mass_kg, 0.0);
  const bool wheels = c.require(Rule::WheelBase, robot.wheel_base_m, 0.0);
  if (body && wheels) c.require(Rule::WheelBaseWithinBody, robot.wheel_base_m, 2 * robot.body_radius_m);
  const bool speed = c.require(Rule::MaxSpeed, robot.motor.max_speed_mps, 0.0);
  c.require(Rule::TimeConstant, robot.motor.time_constant_s, 0.0);
  c.require(Rule::MaxAccel, robot.motor.max_accel_mps2, 0.0);
  c.require(Rule::MotorNoise, robot.motor.noise_sd, 0.0);
  c.require(Rule::IrRange, robot.ir.range_m, 0.0);
  if (c.require(Rule::IrApertureMin, robot.ir.aperture_rad, 0.0))
    c.require(Rule::IrApertureMax, robot.ir.aperture_rad, std::numbers::pi);
  if (c.require(Rule::IrRaysMin, robot.ir.rays, 1)) c.require(Rule::IrRaysMax, robot.ir.rays, kMaxIrRays);
  c.require(Rule::IrNoise, robot.ir.noise_sd, 0.0);
  check_ir_layout(robot, body, c);
  check_ground(robot, body, check_outline(robot, body, c), c);
  c.at_most(Rule::BumperCount, robot.bumpers.size(), kMaxBumpers);
  for (std::size_t i = 0; i < robot.bumpers.size(); ++i) {
    const double width = robot.bumpers[i].width_rad();
    const int at = static_cast<int>(i);
    if (c.require(Rule::BumperSectorMin, width, 0.0, at))
      c.require(Rule::BumperSectorMax, width, 2 * std::numbers::pi + kInsideTolerance_m, at);
  }
  const bool step = c.require(Rule::ControlStep, robot.control_step_s, 0.0);
  const bool substeps = c.require(Rule::SubstepsMin, robot.physics_substeps, 1) &&
                        c.require(Rule::SubstepsMax, robot.physics_substeps, kMaxPhysicsSubsteps);
  c.require(Rule::LightHalfDistance, robot.light.half_distance_m, 0.0);
  c.require(Rule::LightNoise, robot.light.noise_sd, 0.0);
  c.require(Rule::EmissionIntensity, robot.emission.intensity, 0.0);
  c.require(Rule::EmissionHeight, robot.emission.height_m, 0.0);
  if (c.require(Rule::EnergyDischargeMin, robot.energy.discharge_steps, 1))
    c.require(Rule::EnergyDischargeMax, robot.energy.discharge_steps, kMaxEnergySteps);
  if (c.require(Rule::EnergyRechargeMin, robot.energy.recharge_steps, 1))
    c.require(Rule::EnergyRechargeMax, robot.energy.recharge_steps, kMaxEnergySteps);
  c.at_most(Rule::RangefinderCount, robot.rangefinders.angles_rad.size(), kMaxRangefinders);
  c.require(Rule::RangefinderRange, robot.rangefinders.range_m, 0.0);
  if (c.require(Rule::RadarsMin, robot.radars, 0)) c.require(Rule::RadarsMax, robot.radars, kMaxRadars);
  if (robot.drive == DriveKind::Acceleration) {
    c.require(Rule::TurnRate, robot.turn.max_rate_radps, 0.0);
    c.require(Rule::TurnAccel, robot.turn.max_accel_radps2, 0.0);
    c.require(Rule::NoiseWithoutWheels, robot.motor.noise_sd, 0.0);
  } else if (body && wheels && speed && step && substeps) {
    // Fastest point of the body: centre speed plus rim speed, at most
    // max_speed * max(1, 2 R / wheel_base) for commands in [-1, 1].
    const double rim = robot.motor.max_speed_mps * std::max(1.0, 2.0 * robot.body_radius_m / robot.wheel_base_m);
    c.require(Rule::ContactLookAhead, rim * robot.control_step_s / robot.physics_substeps, kMaxTravelPerSubstep_m);
  }
  return out;
}

void validate_arena(const ArenaSpec& arena) {
  if (const auto problems = arena_problems(arena); !problems.empty()) throw_first(problems);
}

void validate_robot(const RobotParams& robot) {
  if (const auto problems = robot_problems(robot); !problems.empty()) throw_first(problems);
}

}  // namespace esc::sim
