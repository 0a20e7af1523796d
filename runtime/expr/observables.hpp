#pragma once
// The variables that compiled expressions, controllers and behaviors read: one flat frame
// of doubles per robot, refilled by the evaluation loop at every control step. The
// compiler resolves a script name (`ir[3]`, `forward_speed`) to a slot of this frame once,
// so reading an observable in the step loop is an array load.
//
// Each observable is documented in docs/language.md; keep the two in step.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace esc::expr {

using Slot = std::uint32_t;

namespace slot {
inline constexpr Slot speed = 0;          // |body displacement| / (dt * max wheel speed), [0, 1]
inline constexpr Slot forward_speed = 1;  // displacement along heading / (dt * max speed), [-1, 1]
inline constexpr Slot wheel_diff = 2;     // |left - right| / 2 of measured wheel speeds, [0, 1]
inline constexpr Slot wheels = 3;         // wheels[0] left, wheels[1] right: measured speed / max
inline constexpr Slot ir = 5;             // ir[0..7]: IR proximity, 0 far .. 1 touching
inline constexpr Slot collision = 13;     // 1 if the body touched a wall or obstacle this step
inline constexpr Slot step = 14;          // index of the control step in the epoch, from 0
inline constexpr Slot time = 15;          // seconds since the epoch started
inline constexpr Slot epoch = 16;         // index of the epoch in the evaluation, from 0
inline constexpr Slot light = 17;         // light[0..7]: ambient light, 0 dark .. 1 bright
inline constexpr Slot energy = 25;        // accumulator level, 0 empty .. 1 full (1 without energy)
inline constexpr Slot com_speed = 26;     // centre-of-mass speed: the same value as `speed`
inline constexpr Slot ground = 27;        // 1 when the centre is over a visible zone
inline constexpr Slot new_cell = 28;      // 1 on the step the centre enters an unvisited grid cell
inline constexpr Slot cells_visited = 29; // grid cells visited this epoch (start cell included)
inline constexpr Slot in_zone = 30;       // in_zone[z]: `in(zone)`, 1 when the centre is in zone z
inline constexpr Slot reached = 38;       // reached[l]: `reached(light)`, 1 on entering light l's reach
inline constexpr Slot noise = 42;         // uniform in [0, 1), fresh at every step of an evaluation
// The experiment-wide id of the action or behavior the compared controller chose at this
// step (ControllerSpec::Choice::id), -1 when it chooses none: what `using(B)` compares.
inline constexpr Slot acting = 43;
inline constexpr Slot param = 44;         // param[0..3]: parameters of the running behavior
// Added after `param`, so that no earlier slot moved (stored programs and genomes' inputs
// name slots): the maze navigator's observables (Lehman & Stanley 2011).
inline constexpr Slot x = 48;             // the body's centre in the arena frame, metres
inline constexpr Slot y = 49;
inline constexpr Slot heading = 50;       // radians from +x, counter-clockwise, in (-pi, pi]
inline constexpr Slot goal_distance = 51; // metres from the centre to the arena's goal
inline constexpr Slot range = 52;         // range[0..7]: rangefinders, distance / range, 1 when clear
inline constexpr Slot radar = 60;         // radar[0..7]: 1 for the pie slice holding the goal
// Added after the navigator's (issue 44): ground sensors at the robot's points (last).
inline constexpr Slot ground_sensor = 68;  // ground_sensor[0..3]: 1 over a visible zone
inline constexpr Slot bumper = 72;         // bumper[0..3]: 1 on a step the body touched within its sector
// Added after `bumper`, as the navigator's were: a group's observables (docs/groups.md), the
// same in every robot's frame but for the robot's own distances.
inline constexpr Slot robots = 76;            // robots in the group, 1 for a robot alone
inline constexpr Slot centroid_x = 77;        // the group's centroid (its centres' mean), metres
inline constexpr Slot centroid_y = 78;
inline constexpr Slot centroid_moved = 79;    // the centroid's distance from where it was at the epoch's start
inline constexpr Slot centroid_distance = 80; // this robot's centre to the centroid
inline constexpr Slot nearest_robot = 81;     // this robot's centre to the nearest other robot's centre
inline constexpr Slot robot_distance = 82;    // the mean distance between two robots' centres
inline constexpr Slot spread = 83;            // the largest distance of a robot's centre to the centroid
// A group's clusters, one slot per radius an experiment reads (`clusters(15cm)`: robots whose
// centres are within the radius of each other, directly or through others, are one cluster).
inline constexpr Slot clusters = 84;          // clusters[k]: how many clusters, a robot alone one
inline constexpr Slot largest_cluster = 88;   // largest_cluster[k]: robots in the largest
inline constexpr Slot cluster_size = 92;      // cluster_size[k]: robots in this robot's cluster
}  // namespace slot

inline constexpr Slot kIrCount = 8;
inline constexpr Slot kLightCount = 8;
inline constexpr Slot kWheelCount = 2;
inline constexpr Slot kMaxZones = 8;      // = sim::kMaxZones (checked in runtime/eval/observe.cpp)
inline constexpr Slot kMaxLights = 4;     // = sim::kMaxLights
inline constexpr Slot kMaxParams = 4;
inline constexpr Slot kRangeCount = 8;    // = sim::kMaxRangefinders
inline constexpr Slot kRadarCount = 8;    // = sim::kMaxRadars
inline constexpr Slot kGroundSensorCount = 4;   // = sim::kMaxGroundSensors
inline constexpr Slot kBumperCount = 4;         // = sim::kMaxBumpers
inline constexpr Slot kMaxClusterRadii = 4;     // radii an experiment's clusters are counted within
inline constexpr Slot kFrameSize = slot::cluster_size + kMaxClusterRadii;

static_assert(slot::light + kLightCount == slot::energy);
static_assert(slot::in_zone + kMaxZones == slot::reached);
static_assert(slot::reached + kMaxLights == slot::noise);
static_assert(slot::noise + 1 == slot::acting && slot::acting + 1 == slot::param);
static_assert(slot::param + kMaxParams == slot::x && slot::x + 1 == slot::y && slot::y + 1 == slot::heading);
static_assert(slot::heading + 1 == slot::goal_distance && slot::goal_distance + 1 == slot::range);
static_assert(slot::range + kRangeCount == slot::radar);
static_assert(slot::radar + kRadarCount == slot::ground_sensor);
static_assert(slot::ground_sensor + kGroundSensorCount == slot::bumper);
static_assert(slot::bumper + kBumperCount == slot::robots);
static_assert(slot::spread + 1 == slot::clusters && slot::clusters + kMaxClusterRadii == slot::largest_cluster);
static_assert(slot::largest_cluster + kMaxClusterRadii == slot::cluster_size);

// The frame's size before `x` and the slots after it existed: what the aggregates' slots
// (below) are numbered from in a fingerprint (runtime/eval/fingerprint.cpp), so that growing
// the frame leaves the fingerprints of stored runs as they were.
inline constexpr Slot kFrameSizeBeforeNavigator = slot::x;

using Frame = std::array<double, kFrameSize>;

// Whether slot `s` describes the last control step alone (a speed over it, a contact or an
// event during it, the choice acting on it) rather than the state the robot is in: read at
// the end of an epoch, it says nothing of the epoch's other steps. A descriptor that reads
// one outside a step aggregate is warned of (`mean(speed)` is the mean over the steps).
[[nodiscard]] constexpr bool describes_last_step(Slot s) noexcept {
  return s == slot::speed || s == slot::forward_speed || s == slot::wheel_diff || s == slot::wheels ||
         s == slot::wheels + 1 || s == slot::collision || s == slot::com_speed || s == slot::new_cell ||
         (s >= slot::reached && s < slot::reached + kMaxLights) || s == slot::noise || s == slot::acting ||
         (s >= slot::bumper && s < slot::bumper + kBumperCount);
}

// The aggregates an end term (a fitness's `epoch:` or `evaluation:` term) reads, in slots
// after the frame: it is evaluated once, on the last step's frame followed by these, over
// the epoch (or the whole evaluation).
namespace aggregate {
inline constexpr Slot steps = kFrameSize;       // control steps the epoch (evaluation) ran
inline constexpr Slot count = kFrameSize + 1;   // count[id]: steps in which choice `id` acted
}  // namespace aggregate

// One script-visible observable: a scalar (count 1, not indexable) or an array.
struct Observable {
  std::string_view name;
  Slot first;
  Slot count;
  bool indexed;
  std::string_view unit;
  std::string_view summary;
};

inline constexpr std::array kObservables = {
    Observable{"speed", slot::speed, 1, false, "fraction of max speed",
               "body speed over the last step (distance covered / step time), 0 .. 1"},
    Observable{"forward_speed", slot::forward_speed, 1, false, "fraction of max speed",
               "speed along the heading over the last step, -1 (backwards) .. 1"},
    Observable{"wheel_diff", slot::wheel_diff, 1, false, "fraction",
               "|left - right| / 2 of the measured wheel speeds, 0 .. 1"},
    Observable{"wheels", slot::wheels, kWheelCount, true, "fraction of max speed",
               "measured wheel speeds, [0] left and [1] right, -1 .. 1"},
    Observable{"ir", slot::ir, kIrCount, true, "activation",
               "IR proximity sensors 0..7 (left to right, then two at the back), 0 far .. 1 touching"},
    Observable{"collision", slot::collision, 1, false, "boolean",
               "1 when the body touched a wall or an obstacle during the last step"},
    Observable{"step", slot::step, 1, false, "count", "control step within the epoch, from 0"},
    Observable{"time", slot::time, 1, false, "s", "time since the epoch started"},
    Observable{"epoch", slot::epoch, 1, false, "count", "epoch within the evaluation, from 0"},
    Observable{"light", slot::light, kLightCount, true, "activation",
               "ambient light sensors 0..7 (at the IR sensors' places), 0 dark .. 1 bright"},
    Observable{"energy", slot::energy, 1, false, "fraction",
               "accumulator level, 0 empty .. 1 full (1 when the robot has no energy model)"},
    Observable{"com_speed", slot::com_speed, 1, false, "fraction of max speed",
               "speed of the centre of mass over the last step, 0 .. 1 (the value of `speed`)"},
    Observable{"ground", slot::ground, 1, false, "boolean",
               "1 when the robot's centre is over a visible zone (the ground sensor)"},
    Observable{"new_cell", slot::new_cell, 1, false, "boolean",
               "1 on a step when the centre entered a grid cell not yet visited this epoch"},
    Observable{"cells_visited", slot::cells_visited, 1, false, "count",
               "grid cells visited in this epoch, the start cell included"},
    Observable{"noise", slot::noise, 1, false, "fraction",
               "uniform random in [0, 1), new at every step, reproducible from the evaluation's seed"},
    Observable{"x", slot::x, 1, false, "m", "the robot's centre in the arena, from its left wall"},
    Observable{"y", slot::y, 1, false, "m", "the robot's centre in the arena, from its bottom wall"},
    Observable{"heading", slot::heading, 1, false, "rad",
               "the robot's heading, counter-clockwise from +x, -pi .. pi"},
    Observable{"goal_distance", slot::goal_distance, 1, false, "m",
               "distance from the robot's centre to the arena's goal (needs a `goal`)"},
    Observable{"range", slot::range, kRangeCount, true, "fraction of range",
               "rangefinders in the robot's order: distance to the nearest wall or obstacle / range, 1 when "
               "nothing is within range (needs `rangefinders`)"},
    Observable{"radar", slot::radar, kRadarCount, true, "boolean",
               "goal radars: 1 for the pie slice holding the goal, 0 else; slice 0 ahead, then counter-clockwise "
               "(needs `radars` and a `goal`)"},
    Observable{"ground_sensor", slot::ground_sensor, kGroundSensorCount, true, "boolean",
               "ground sensors in the robot's order: 1 over a visible zone, 0 elsewhere (needs `ground_sensors`; "
               "the robot may name them otherwise, the Thymio's `prox_ground`)"},
    Observable{"bumper", slot::bumper, kBumperCount, true, "boolean",
               "bumpers in the robot's order: 1 on a step in which the body touched a wall, an obstacle or another "
               "robot within the bumper's sector (needs `bumpers`)"},
    Observable{"robots", slot::robots, 1, false, "count", "robots in the group (`robot NAME x N`), 1 alone"},
    Observable{"centroid_x", slot::centroid_x, 1, false, "m", "the group's centroid (the mean of its centres)"},
    Observable{"centroid_y", slot::centroid_y, 1, false, "m", "the group's centroid (the mean of its centres)"},
    Observable{"centroid_moved", slot::centroid_moved, 1, false, "m",
               "how far the group's centroid is from where it was at the epoch's start"},
    Observable{"centroid_distance", slot::centroid_distance, 1, false, "m",
               "distance from the robot's centre to the group's centroid (0 alone)"},
    Observable{"nearest_robot", slot::nearest_robot, 1, false, "m",
               "distance from the robot's centre to the nearest other robot's (the arena's diagonal alone)"},
    Observable{"robot_distance", slot::robot_distance, 1, false, "m",
               "the mean distance between two robots' centres, over every pair (0 alone)"},
    Observable{"spread", slot::spread, 1, false, "m",
               "the largest distance of a robot's centre to the group's centroid (0 alone)"},
};

// Observables that take an argument: a thing of the arena, `in(zone)` and `reached(light)`,
// or a length, a group's `clusters(15cm)`: a block of `count` slots from `first`, one per
// zone (light) in the order the arena declares them, so `in(recharge)` reads slot in_zone +
// index of zone `recharge`, or one per radius in the order the experiment first reads them
// (eval::ExperimentSpec::cluster_radii). They are not in kObservables: a bare `in` or
// `reached` is not an observable, and the GP terminal set and the compiler's name lists do
// not see them.
struct ParametrisedObservable {
  std::string_view name;
  Slot first;
  Slot count;              // the most arguments an arena (an experiment) may have
  std::string_view argument;  // what the argument is: "zone", "light" or "radius" (a length)
  std::string_view unit;
  std::string_view summary;
};

inline constexpr std::array kParametrised = {
    ParametrisedObservable{"in", slot::in_zone, kMaxZones, "zone", "boolean",
                           "1 when the robot's centre is inside the zone (visible or not)"},
    ParametrisedObservable{"reached", slot::reached, kMaxLights, "light", "boolean (event)",
                           "1 on the step the robot's centre comes within the arena's reach "
                           "radius of the light (rising edge: 0 while it stays there)"},
    ParametrisedObservable{"clusters", slot::clusters, kMaxClusterRadii, "radius", "count",
                           "how many clusters the group makes, robots whose centres are within the radius of "
                           "each other (directly or through others) being one; 1 alone"},
    ParametrisedObservable{"largest_cluster", slot::largest_cluster, kMaxClusterRadii, "radius", "count",
                           "robots in the group's largest cluster within the radius; 1 alone"},
    ParametrisedObservable{"cluster_size", slot::cluster_size, kMaxClusterRadii, "radius", "count",
                           "robots in this robot's cluster within the radius, itself included; 1 alone"},
};

[[nodiscard]] constexpr std::optional<Observable> find_observable(std::string_view name) noexcept {
  for (const auto& o : kObservables)
    if (o.name == name) return o;
  return std::nullopt;
}

// Every observable's script name, in slot order (what "did you mean" suggests from).
[[nodiscard]] inline std::vector<std::string> observable_names() {
  std::vector<std::string> names;
  for (const auto& o : kObservables) names.emplace_back(o.name);
  return names;
}

[[nodiscard]] constexpr std::optional<ParametrisedObservable> find_parametrised(
    std::string_view name) noexcept {
  for (const auto& o : kParametrised)
    if (o.name == name) return o;
  return std::nullopt;
}

// `wheel_diff`, `range[3]`: slot `s` as scripts name it; none for a slot scripts do not read
// by a name of its own (the choice acting, the noise, the lights reached).
[[nodiscard]] std::optional<std::string> observable_name(Slot s);

}  // namespace esc::expr
