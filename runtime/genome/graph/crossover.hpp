#pragma once
// NEAT's crossover (the paper, section 3.2; NEAT C++'s mate_multipoint and
// mate_multipoint_avg): the parents' links are lined up by innovation; a matching link comes
// from either parent at random (or, averaged, with the mean weight); disjoint and excess
// links come from the fitter parent only, and with equal fitness from the one with fewer
// links (NEAT C++'s rule; the paper draws them from both). A link disabled in either parent
// is disabled in the child with probability 0.75. A link joining two nodes the child
// already joins is left out. The child has every sensor and output of `dad`, and the
// hidden nodes its links reach.
#include "runtime/core/rng.hpp"
#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

enum class Mating : std::uint8_t {
  Multipoint,          // a matching link from one parent, chosen evenly
  MultipointAverage,   // a matching link with the parents' mean weight
};

// `mom_fitness` and `dad_fitness` decide which parent's disjoint and excess links pass.
[[nodiscard]] Graph mate(const Graph& mom, const Graph& dad, double mom_fitness, double dad_fitness, Mating how,
                         Rng& rng);

// The probability that a link disabled in either parent stays disabled in the child.
inline constexpr double kKeepDisabled = 0.75;

}  // namespace esc::genome::graph
