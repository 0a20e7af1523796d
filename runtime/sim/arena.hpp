#pragma once
// The static world a robot runs in, as the compiler produces it: a walled rectangle with
// box and cylinder obstacles. All lengths in metres, angles in radians; the origin is the
// arena's lower-left inner corner, x to the right, y up, heading 0 along +x.
#include <optional>
#include <vector>

namespace esc::sim {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

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

struct ArenaSpec {
  double width_m = 0.6;   // inner size of the walled rectangle
  double height_m = 0.6;
  std::vector<BoxObstacle> boxes;
  std::vector<CylinderObstacle> cylinders;
  std::optional<Pose> fixed_start;   // none: a random pose, never inside an obstacle
};

}  // namespace esc::sim
