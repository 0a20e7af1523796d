#pragma once
// NSGA-II (nsga2.hpp) as an Optimizer of a network's weights, or of trees with the GP's
// operators (genome/tree/tree_variation.hpp, settings from problem.tree.operators; candidates go out
// encoded), over every objective of an Outcome: it starts from Rng(seed, Init) (or the start genome, then candidate 0 of
// generation 0), breeds generation g from Rng(seed, Breed, g) and minimises the negated
// objectives. Its metrics: the size of the first front and, for 2 or 3 objectives whose
// ranges are all declared, the front's hypervolume with the declared worst values as the
// reference point (in the objectives' maximised terms, a minimised one counted negated).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::evo {

// Throws std::invalid_argument on impossible settings (check_nsga2_settings, the GP's for a
// tree) or a tree without the GP's settings.
[[nodiscard]] std::unique_ptr<Optimizer> make_nsga2(const Nsga2Settings& settings, const Problem& problem);

// NSGA-II's core for `problem`: over its network's weights in the settings' box, or over
// its trees. What NSGA-II and novelty search, which breeds as NSGA-II does, start from.
[[nodiscard]] Nsga2 nsga2_core(const Nsga2Settings& settings, const Problem& problem);

// Candidates per generation: the population.
[[nodiscard]] std::size_t nsga2_population(const Nsga2Settings& settings, const Problem& problem);

// What one run's NSGA-II holds at its peak (nsga2_memory_bytes, with every objective) and
// where the parents were measured.
[[nodiscard]] MemoryPeak nsga2_memory_peak(const Nsga2Settings& settings, const Problem& problem);

// The hypervolume's reference point in the core's minimised terms (each objective's declared
// worst value, negated), or empty when there are not 2 or 3 objectives or one has no range.
[[nodiscard]] std::vector<double> hypervolume_reference(const Problem& problem);

// Where the survivors of a tell were measured: `kept` as Nsga2::tell returns it (indices into
// the parents, then the candidates of `generation`'s ask), `parents` aligned with the parents.
[[nodiscard]] std::vector<Measured> survivors_measured(const std::vector<Measured>& parents, int generation,
                                                       std::span<const std::size_t> kept);

}  // namespace esc::evo
