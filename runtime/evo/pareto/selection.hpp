#pragma once
// NSGA-II's selection by rank and crowding (Deb et al. 2002, sections III-B and III-C),
// without any variation operator: what a variant with other genomes (trees) or other
// operators reuses. Objectives are minimised (fronts.hpp).
#include <cstddef>
#include <vector>

#include "runtime/evo/pareto/fronts.hpp"

namespace esc::evo {

// Per point: its front (0 is the non-dominated one) and its crowding distance within that
// front (never NaN: fronts.hpp).
struct Ranking {
  std::vector<std::size_t> rank;
  std::vector<double> crowding;
};

// Every point's front and crowding distance.
[[nodiscard]] Ranking rank_and_crowd(const ObjectiveRows& f);

// The crowded-comparison operator of the paper (III-C): a goes before b when its rank is
// lower, or the ranks are equal and its crowding distance larger. Equal in both, the lower
// index goes first, so this is a strict total order and nothing depends on a coin or on
// sort stability.
[[nodiscard]] bool crowded_before(const Ranking& r, std::size_t a, std::size_t b) noexcept;

// The winner of a binary tournament between a and b under crowded_before.
[[nodiscard]] std::size_t crowded_tournament(const Ranking& r, std::size_t a, std::size_t b) noexcept;

// NSGA-II's environmental selection: the n points kept, ascending. Whole fronts in order
// while they fit, then the points of the next front with the largest crowding distance (ties
// by index): the first n points under crowded_before. Throws std::invalid_argument when n
// exceeds the number of points or the ranking's two vectors differ in length.
[[nodiscard]] std::vector<std::size_t> select_survivors(const Ranking& r, std::size_t n);
[[nodiscard]] std::vector<std::size_t> select_survivors(const ObjectiveRows& f, std::size_t n);

}  // namespace esc::evo
