#pragma once
// A body that is not a disc: a convex outline in the body's frame (x along the heading, y to
// the left, from the point the wheels turn about), the Thymio II's rounded front and flat
// back. Plain geometry, no Bullet: the checks the robot's rules make, the inertia and the
// inset the Bullet hull is built from (body.cpp), and the outline placed in the world for the
// contact test (geometry2d.hpp).
#include <span>
#include <vector>

#include "runtime/sim/arena.hpp"

namespace esc::sim {

// Twice the signed area: positive when the vertices go counter-clockwise.
[[nodiscard]] double twice_signed_area(std::span<const Vec2> outline) noexcept;

// The vertices counter-clockwise (the order given, or reversed).
[[nodiscard]] std::vector<Vec2> counter_clockwise(std::span<const Vec2> outline);

// The smallest turn at a vertex, as the cross product of the edges meeting there (unit
// edges: the sine of the turn), in the outline's own direction: positive at every vertex of a
// strictly convex outline, whichever way it goes round; 0 at the vertex where an outline
// turning one way winds round a second time (a star). Which vertex gives it: `at`.
[[nodiscard]] double smallest_turn(std::span<const Vec2> outline, int& at) noexcept;

// How far inside the outline `p` lies (its origin by default): the least distance to an
// edge's line, negative when it is outside an edge (a convex, counter-clockwise outline).
[[nodiscard]] double origin_depth(std::span<const Vec2> ccw, Vec2 p = {}) noexcept;

// The smallest interior angle (radians) of a convex, counter-clockwise outline, and at which
// vertex (`at`).
[[nodiscard]] double smallest_corner(std::span<const Vec2> ccw, int& at) noexcept;

// The outline moved in by `margin` on every edge (a convex, counter-clockwise outline much
// larger than the margin): Bullet grows a hull by its collision margin, so the hull of the
// inset is the outline itself, its corners rounded by the margin.
[[nodiscard]] std::vector<Vec2> inset(std::span<const Vec2> ccw, double margin);

// The moment of inertia about the origin, per unit mass, of a uniform plate of this shape
// (a convex, counter-clockwise outline): the polar second moment over the area.
[[nodiscard]] double polar_gyration_sq(std::span<const Vec2> ccw) noexcept;

// Points of the body's frame (an outline, the ground sensors) at `pose`, into `out` (as many
// points as `outline`).
void place_points(std::span<const Vec2> outline, const Pose& pose, std::span<Vec2> out) noexcept;

}  // namespace esc::sim
