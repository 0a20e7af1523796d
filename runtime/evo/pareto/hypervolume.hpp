#pragma once
// The hypervolume indicator (Zitzler & Thiele 1998): the volume of the region the points
// dominate, bounded by a reference point, objectives minimised. It measures a whole front,
// how close it lies to the optimum and how widely it spreads; scripts/validate-nsga2.py and
// the tests compare NSGA-II runs by it.
#include <span>

#include "runtime/evo/pareto/fronts.hpp"

namespace esc::evo {

// Exact, for 2 or 3 objectives. Only points strictly better than the reference in every
// objective count (the others, NaN included, add nothing). Two objectives: the points
// sorted by the first objective, each adds the rectangle between its second objective and
// the best one before it, O(N log N). Three: slicing along the third objective (the
// "hypervolume by slicing objectives" idea of While et al., IEEE TEC 10(1), 2006): the
// points sorted by it, the 2-D area of those at or below each slice times the slice's
// depth, O(N^2). Throws std::invalid_argument for another number of objectives, a
// non-finite reference, or a point of another length. Every product and sum saturates at the
// largest double, so the volume is finite even for points far below a declared reference.
[[nodiscard]] double hypervolume(const ObjectiveRows& points, std::span<const double> reference);

}  // namespace esc::evo
