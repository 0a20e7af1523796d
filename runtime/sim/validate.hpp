#pragma once
// The rules an arena and a robot must satisfy before a World is built, and why (physics
// limits of the simulator). One rule set for the whole program: the World refuses to
// build on a broken rule (validate_arena, validate_robot throw), and the compiler asks the
// same functions for every problem (arena_problems, robot_problems, placement_problems)
// and reports each at the setting of the script that broke it, so a script `esc check`
// accepts never fails validation in `esc run`.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/sim/arena.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::sim {

// Largest distance a point of the body may travel in one physics substep: Bullet creates
// contact points (which the solver uses to stop the body at a surface) only within this
// look-ahead, Bullet's gContactBreakingThreshold (0.02 m), of which we allow half.
inline constexpr double kMaxTravelPerSubstep_m = 0.01;

// The area-sweeping grid holds at most this many cells (one bit each).
inline constexpr double kMaxSweepCells = 1e8;

// discharge_steps and recharge_steps are at most this: the accumulator counts in integer
// units, discharge_steps * recharge_steps * physics_substeps of them, in 64 bits.
inline constexpr int kMaxEnergySteps = 10'000'000;

// Bullet's sweep-and-prune broadphase indexes objects with 16-bit handles.
inline constexpr std::size_t kMaxObstacles = 30000;

// The IR model spreads at most this many rays per sensor; the physics step count is capped
// so that one control step stays a bounded amount of work.
inline constexpr int kMaxIrRays = 64;
// A measured IR response holds at most this many points.
inline constexpr std::size_t kMaxIrResponsePoints = 64;
inline constexpr int kMaxPhysicsSubsteps = 1000;

// Every rule, one per relation checked (a range is two rules).
enum class Rule {
  // the arena alone
  ArenaWidth, ArenaHeight, ObstacleCount, BlockSize, BlockInside, CylinderRadius, CylinderInside,
  WallLength, WallThickness, WallInside, StartInside, GoalInside, ZoneCount, ZoneRadius, ZoneSize,
  ZoneInside, ZoneFits, LightCount, LightHeight, LightIntensity, LightZone, LightInside, SweepCell,
  SweepGrid, ReachRadius,
  // the robot in the arena
  RobotFits, StartClearOfWalls, StartClearOfCylinder, StartClearOfBlock, StartClearOfWall,
  // the robot alone
  BodyRadius, BodyHeight, Mass, WheelBase, WheelBaseWithinBody, MaxSpeed, TimeConstant, MaxAccel, MotorNoise,
  IrRange, IrApertureMin, IrApertureMax, IrRaysMin, IrRaysMax, IrNoise, IrCount, IrMountRadiusMin,
  IrMountRadiusMax, IrCurve, IrResponseCount, IrResponseStart, IrResponseDistance, IrResponseReadingMin, IrResponseReadingMax,
  ControlStep, SubstepsMin,
  SubstepsMax, LightHalfDistance, LightNoise, EnergyDischargeMin, EnergyDischargeMax,
  EnergyRechargeMin, EnergyRechargeMax, RangefinderCount, RangefinderRange, RadarsMin, RadarsMax,
  ContactLookAhead, TurnRate, TurnAccel, NoiseWithoutWheels, OutlineCountMin, OutlineCountMax, OutlineConvex,
  OutlineAroundCentre, OutlineWithinRadius, OutlineWithoutWheels, GroundCount, GroundMountRadiusMin,
  GroundMountRadiusMax, BumperCount, BumperSectorMin, BumperSectorMax, OutlineCorner, OutlineThin,
  GroundUnderOutline, EmissionIntensity, EmissionHeight,
};

enum class Object { Arena, Placement, Robot };

// What the value found must be, compared with the limit.
enum class Relation { Above, AtLeast, Below, AtMost };

// What the value and the limit measure, so that a caller can show them in its own units.
enum class Dimension { Count, Number, Length, Angle, Time, Speed, Acceleration, Mass, TurnRate, TurnAcceleration };

struct RuleInfo {
  Rule rule;
  Object object;
  // What the rule is about, in the script's vocabulary: a robot setting (`ir_aperture`) or a
  // part of an arena (`size`, `sweep_cell`, `reach_radius`, `zone`, `light`, `cylinder`,
  // `block`, `wall`, `goal`, `start`).
  std::string_view setting;
  // Other settings the value depends on (a problem is best shown at whichever of them the
  // script wrote last), or empty.
  std::span<const std::string_view> also;
  Relation relation;
  Dimension dimension;
  // The runtime's name of what is measured, `{}` standing for the index (zone, light, ...).
  std::string_view field;
  std::string_view why;   // the reason for the rule, one phrase
};

// One broken rule: `found` breaks `relation` to `limit` (both in SI units of the rule's
// dimension).
struct Problem {
  Rule rule;
  int index = -1;   // which zone, light, cylinder, block or wall (in the spec's order), else -1
  double found = 0.0;
  double limit = 0.0;

  [[nodiscard]] const RuleInfo& info() const noexcept;
  // The runtime's own sentence, naming the field ("robot.ir.aperture_rad must be below
  // 3.14159 (got 4): ...").
  [[nodiscard]] std::string message() const;
};

// Every rule, in the order of `Rule`.
[[nodiscard]] std::span<const RuleInfo> rules() noexcept;
[[nodiscard]] const RuleInfo& rule_info(Rule r) noexcept;
// "above", "at least", "below", "at most".
[[nodiscard]] std::string_view relation_words(Relation r) noexcept;

// Every broken rule, in rule order within each part; empty when all hold. Rules that need
// a valid size (inside the arena, the sweep grid) are skipped while the size is broken;
// the robot's contact look-ahead only when the values it reads are valid.
[[nodiscard]] std::vector<Problem> arena_problems(const ArenaSpec& arena);
[[nodiscard]] std::vector<Problem> robot_problems(const RobotParams& robot);
// The robot fits the arena and a fixed start keeps its body clear of walls and obstacles
// (meaningful only when the arena and the robot are valid on their own).
[[nodiscard]] std::vector<Problem> placement_problems(const ArenaSpec& arena, const RobotParams& robot);

// Throw std::invalid_argument with the first problem's message (the World's guard).
void validate_arena(const ArenaSpec& arena);
void validate_robot(const RobotParams& robot);

}  // namespace esc::sim
