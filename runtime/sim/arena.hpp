#pragma once
// The static world a robot runs in, as the compiler produces it: a walled rectangle with
// box and cylinder obstacles, segment walls, light sources, floor zones, a goal point and the
// grid used to measure area sweeping. All lengths in metres, angles in radians; the origin is
// the arena's lower-left inner corner, x to the right, y up, heading 0 along +x.
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace esc::sim {

// Most lights and zones an arena may hold: the observable frame reserves one slot per
// light for `reached(light)` and one per zone for `in(zone)` (runtime/expr/observables.hpp).
inline constexpr std::size_t kMaxLights = 4;
inline constexpr std::size_t kMaxZones = 8;

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

// The plane's two products the outline and polygon routines share: a - b, and a x b (positive
// when b turns counter-clockwise from a).
[[nodiscard]] inline Vec2 minus(Vec2 a, Vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
[[nodiscard]] inline double cross(Vec2 a, Vec2 b) noexcept { return a.x * b.y - a.y * b.x; }

// The point at `distance_m` from the origin along `bearing_rad` (a mount's place on the body).
[[nodiscard]] inline Vec2 polar(double bearing_rad, double distance_m) noexcept {
  return {distance_m * std::cos(bearing_rad), distance_m * std::sin(bearing_rad)};
}

struct Pose {
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_rad = 0.0;
};

struct BoxObstacle {
  Vec2 center_m;
  Vec2 size_m;          // full extent along x and y before rotation
  double angle_rad = 0.0;
};

struct CylinderObstacle {
  Vec2 center_m;
  double radius_m = 0.0;
};

// Default thickness of a segment wall: thin against the 55 mm body, and 20 times Bullet's
// collision margin (0.5 mm), so the contact solver meets a solid box.
inline constexpr double kDefaultWallThickness_m = 0.01;

// A wall of a maze (Lehman & Stanley 2011's line segments): the rectangle of the segment's
// length and `thickness_m` centred on the segment from `from_m` to `to_m`, its ends square at
// the end points. Every part of the simulator sees exactly that rectangle (wall_box).
struct WallSegment {
  Vec2 from_m;
  Vec2 to_m;
  double thickness_m = kDefaultWallThickness_m;
};

// The wall's rectangle as a rotated box.
[[nodiscard]] inline BoxObstacle wall_box(const WallSegment& w) noexcept {
  const double dx = w.to_m.x - w.from_m.x;
  const double dy = w.to_m.y - w.from_m.y;
  return {{(w.from_m.x + w.to_m.x) / 2, (w.from_m.y + w.to_m.y) / 2}, {std::hypot(dx, dy), w.thickness_m},
          std::atan2(dy, dx)};
}

// A point light seen by the ambient-light sensors (docs/robot-model.md, "Ambient light").
struct LightSource {
  Vec2 position_m;          // floor position; ignored when above_zone >= 0
  double height_m = 0.0;    // above the sensors' plane (0: a lamp at sensor height)
  double intensity = 1.0;   // relative; a light of 1 read head-on at distance 0 gives 1
  int above_zone = -1;      // index of a zone: the light stands above its centre and
                            // follows it when the zone is placed at random; -1: fixed
};

enum class ZoneShape { Circle, Rectangle };

// A region of the floor: a circle or an axis-aligned rectangle. The robot is "in" a zone
// when its centre is inside it (boundary included).
struct Zone {
  ZoneShape shape = ZoneShape::Circle;
  Vec2 center_m;              // ignored when random_position (then the arena's centre
                              // until World::place_zones draws a position)
  double radius_m = 0.0;      // Circle
  Vec2 size_m;                // Rectangle: full extent along x and y
  bool visible = false;       // seen by the ground sensor (`ground`); invisible zones are not
  bool random_position = false;  // placed uniformly at each epoch start by World::place_zones,
                                 // inside the arena and clear of every obstacle
  bool recharge = false;      // the energy accumulator refills while the robot is inside
};

// Default reach radius of `reached(light)`: the Khepera's body radius (27.5 mm) + 2 cm.
inline constexpr double kDefaultReachRadius_m = 0.0475;
// Default cell size of the area-sweeping grid.
inline constexpr double kDefaultSweepCell_m = 0.04;

struct ArenaSpec {
  double width_m = 0.6;   // inner size of the walled rectangle
  double height_m = 0.6;
  std::vector<BoxObstacle> boxes;
  std::vector<CylinderObstacle> cylinders;
  std::vector<WallSegment> walls;    // segment walls, obstacles like the boxes
  std::optional<Pose> fixed_start;   // none: a random pose, never inside an obstacle
  std::vector<LightSource> lights;   // at most kMaxLights
  std::vector<Zone> zones;           // at most kMaxZones
  std::optional<Vec2> goal;          // the point `goal_distance` and the goal radars read
  double sweep_cell_m = kDefaultSweepCell_m;      // side of the square cells of `new_cell`
  double reach_radius_m = kDefaultReachRadius_m;  // `reached(light)`: centre within this of
                                                  // the light's floor position
};

}  // namespace esc::sim
