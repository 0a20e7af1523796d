#pragma once
// NSGA-II (nsga2.hpp) as an Optimizer of a network's weights, of trees with the GP's
// operators (genome/tree/tree_variation.hpp, settings from problem.tree.operators; candidates go out
// encoded), or of NEAT networks with NEAT's (genome/graph/graph_variation.hpp, settings from
// problem.graph.operators), over every objective of an Outcome: it starts from Rng(seed, Init) (or the start genome, then candidate 0 of
// generation 0), breeds generation g from Rng(seed, Breed, g) and minimises the negated
// objectives. Its metrics: the size of the first front and, for 2 or 3 objectives whose
// ranges are all declared, the front's hypervolume with the declared worst values as the
// reference point (in the objectives' maximised terms, a minimised one counted negated).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/nsga2/nsga2_options.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

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

// NSGA-II as the registry holds it (registry.hpp): its name, the genomes it evolves (a
// network's weights in a box, or trees varied by the tree kind's operators), and how its
// settings make an optimizer, size a generation, weigh in memory and read in scripts.
struct Nsga2Algorithm {
  using Settings = Nsga2Settings;
  std::string_view name = "nsga2";
  std::string_view what = "NSGA-II";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree, genome::GenomeKind::Graph};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_nsga2(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return nsga2_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return nsga2_memory_peak(s, p);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return nsga2_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return nsga2_problem(s, p); }
};

}  // namespace esc::evo
