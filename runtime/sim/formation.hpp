#pragma once
// Where a group's robots start each epoch (docs/groups.md): at random free places, one after
// the other (the default), in a formation about a centre and a heading drawn each epoch from
// the epoch's stream (a line of robots side by side, facing the heading; a circle, each
// facing out), or at poses the script gives.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

enum class FormationKind { Random, Line, Circle, At };

struct Formation {
  FormationKind kind = FormationKind::Random;
  // Line: between neighbours' centres; Circle: the circle's radius.
  double spacing_m = 0.0;
  std::vector<Pose> at;   // At: robot i's pose, one per robot
};

// Robot i's pose in a Line or Circle formation of `n` robots about `centre` with `heading`:
// a line of robots side by side, perpendicular to the heading and facing it, centred on
// `centre`; a circle of radius spacing_m about it, robot 0 at the heading, counter-clockwise,
// each facing out.
[[nodiscard]] Pose formation_pose(const Formation& f, std::size_t n, std::size_t i, Vec2 centre, double heading) noexcept;

// The farthest a Line or Circle formation of `n` robots puts a centre from the formation's
// centre.
[[nodiscard]] double formation_reach(const Formation& f, std::size_t n) noexcept;

// The nearest two robots' centres come in a Line or Circle formation of `n` robots (no limit
// for one robot).
[[nodiscard]] double formation_closest(const Formation& f, std::size_t n) noexcept;

// Why robots of radii `radii_m` (robot i's, one per robot) cannot take formation `f` in
// `arena`, each body kept `margin_m` clear of the walls, the obstacles and each other; empty
// when they can. Line and Circle (every place kept as the largest body is): a spacing that
// makes neighbours overlap, or a formation wider than the arena. At: not one pose per robot,
// a pose whose body is not clear, two bodies overlapping.
[[nodiscard]] std::string formation_problem(const Formation& f, const ArenaSpec& arena, std::span<const double> radii_m,
                                            double margin_m);

}  // namespace esc::sim
