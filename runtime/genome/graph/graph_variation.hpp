#pragma once
// Graph genomes as NSGA-II, novelty search and MAP-Elites evolve them: NEAT's operators
// (graph_operators.hpp, crossover.hpp) on genomes in their flat form (codec.hpp), so that
// those algorithms keep, rank and store NEAT networks as they do a network's weights or
// trees. The settings are NEAT's (`evolve neat(...)`, or its defaults). Selection and
// population are the algorithm's own; NEAT's speciation and fitness sharing are not used.
//
// Innovation numbers: NEAT gives the same structural mutation within a generation the same
// number, and numbers new ones past every one given before. Here the counters restart, at
// each generation, past every number and node id in the genomes bred from (begin()): the
// parents, or the archive's elites. A number given to a child that did not survive may be
// given again to another structure, which no living genome confuses with it; and the
// counters need no state of their own, so a run resumed from its parents or archive
// numbers its children as the unbroken run does.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/genome/graph/graph_operators.hpp"
#include "runtime/genome/graph/graph_space.hpp"
#include "runtime/genome/representation.hpp"

namespace esc::genome::graph {

class GraphVariation final : public Representation {
 public:
  // Throws std::invalid_argument for a space that evolves no graphs.
  GraphVariation(const GraphOperators& operators, const GraphSpace& space);

  [[nodiscard]] std::string_view what() const override { return "NEAT networks"; }
  [[nodiscard]] std::string_view tag() const override { return "-graphs"; }
  [[nodiscard]] std::size_t genes() const override { return 0; }
  // `count` copies of NEAT's start genome (start_graph), every weight drawn in
  // [-kStartWeight, kStartWeight], genome by genome.
  [[nodiscard]] std::vector<Genome> first(std::size_t count, Rng& rng) const override;
  // Not a graph genome, or one of other inputs or outputs.
  [[nodiscard]] std::string misfit(std::span<const double> genome) const override;
  [[nodiscard]] std::vector<FixedSetting> fixed() const override { return {}; }

  // A generation begins: its new numbers start past every one in `bred_from`.
  void begin(std::span<const Genome> bred_from);

  // NSGA-II's variation of two winners into two children, in place, each made from its own
  // parent as the fitter one and the other: one uniform; below mutate_only_prob, a copy of
  // its parent mutated; else NEAT's crossover (one uniform for multipoint or averaged, then
  // its draws), mutated unless a uniform falls below mate_only_prob. a first, then b.
  void cross_and_mutate(Genome& a, Genome& b, Rng& rng);

  // MAP-Elites' variation of one elite: NEAT's mutation of a copy (mutate()).
  [[nodiscard]] Genome mutate_one(std::span<const double> parent, Rng& rng);

 private:
  [[nodiscard]] Graph decoded(std::span<const double> genome) const;
  [[nodiscard]] Graph child_of(const Graph& own, const Graph& other, Rng& rng);

  GraphOperators ops_;
  GraphSpace space_;
  std::optional<InnovationRecord> record_;   // this generation's, from begin()
};

// Doubles a graph genome of `space` takes once grown to twice its start's links and one
// hidden node per output: what memory estimates count per candidate.
[[nodiscard]] std::size_t typical_encoded_size(const GraphSpace& space);

}  // namespace esc::genome::graph
