#pragma once
// Pareto fronts of a set of objective vectors, all MINIMISED, and the crowding distance
// within a front: the two orders NSGA-II (Deb, Pratap, Agarwal & Meyarivan, IEEE TEC 6(2),
// 2002) selects by, kept apart from any variation operator so that another representation
// (trees, behaviours) can use them.
//
// NaN: a point with a NaN objective can be neither compared nor measured, so it neither
// dominates nor is dominated; all such points form the last front, after every point
// without one, and their crowding distance is 0. Infinite objectives compare as numbers.
#include <cstddef>
#include <span>
#include <vector>

namespace esc::evo {

// Objective vectors, one row per point, all of one length (the number of objectives).
using ObjectiveRows = std::vector<std::vector<double>>;

// a dominates b: no worse in every objective and better in one (minimisation). False when
// either holds a NaN.
[[nodiscard]] bool dominates(std::span<const double> a, std::span<const double> b) noexcept;

// The fronts of Deb's fast non-dominated sort (2002, section III-A) in order (the first
// dominated by no point), indices ascending within each, in O(N) memory: for two objectives
// in O(N log N) time (Jensen 2003), for more in O(M N^2). Every index of f appears
// once. Throws std::invalid_argument when the rows differ in length or have none.
[[nodiscard]] std::vector<std::vector<std::size_t>> nondominated_fronts(const ObjectiveRows& f);

// Deb's crowding distance (2002, section III-B) of the points `front` (indices into f),
// aligned with `front`: per objective, the points sorted by value (ties by index, so equal
// values never depend on sort stability), the two extremes infinite, each other point adding
// the gap between its neighbours over the objective's range in the front. An objective whose
// range is 0 or infinite adds nothing to the inner points (its extremes are still infinite).
// A point with a NaN objective gets 0; the others are measured among themselves, and when
// they are one or two, they are infinite. Unlike DEAP's, the sum is not divided by the
// number of objectives: a common factor that changes no comparison. Throws
// std::invalid_argument for an index outside f or rows of different lengths.
[[nodiscard]] std::vector<double> crowding_distance(const ObjectiveRows& f, std::span<const std::size_t> front);

}  // namespace esc::evo
