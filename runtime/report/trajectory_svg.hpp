#pragma once
// A picture of a controller's behaviour for papers and slides (`esc replay`): the arena to
// scale (walls, obstacles, floor zones where they were in each epoch, lights), the robot's
// path in every epoch drawn, coloured by the action or behavior acting at each step (by
// epoch for a classical head, which has none), where each epoch starts and ends, every
// collision, and a legend. Plain SVG 1.1 with no script or external resource, so it
// prints, converts (rsvg-convert, Inkscape, ImageMagick) and embeds as it is.
#include <span>
#include <string>
#include <vector>

#include "runtime/eval/evaluator.hpp"
#include "runtime/sim/arena.hpp"

namespace esc::report {

struct TrajectoryFigure {
  std::string title;                        // above the arena
  std::string subtitle;                     // under the title (fitness, seed, ...)
  sim::ArenaSpec arena;
  // Robot k's body (sim::RobotParams' body_radius_m and outline; an empty outline: the disc) is
  // bodies[k], or the last one for the robots beyond it (one for a robot alone, or robots alike).
  struct Body {
    double radius_m = 0.0;
    std::vector<sim::Vec2> outline_m;
  };
  std::vector<Body> bodies;
  std::vector<std::string> choices;         // action or behavior names; empty: classical head
  std::span<const eval::TraceStep> steps;   // the epochs drawn, each in step order
};

[[nodiscard]] std::string trajectory_svg(const TrajectoryFigure& figure);

}  // namespace esc::report
