#pragma once
// Trees as NSGA-II, novelty search and MAP-Elites evolve them: the paper's GP operators
// (tree_operators.hpp) on trees encoded as doubles (codec.hpp), so that those algorithms keep, rank
// and store genomes as they do a network's weights. Settings are the experiment's
// `evolve gp(...)`: the first genomes by ramped half-and-half (init_min_depth ..
// init_max_depth), subtree crossover with probability `crossover`, the mutation mix
// (subtree, point, hoist at their probabilities), max_depth and max_size. Selection and
// population size are the algorithm's own.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/genome/representation.hpp"
#include "runtime/genome/tree/tree_operators.hpp"
#include "runtime/genome/tree/tree_space.hpp"

namespace esc::genome::tree {

class TreeVariation final : public Representation {
 public:
  // Throws std::invalid_argument for operators that cannot vary trees of `set`
  // (check_operators).
  TreeVariation(const TreeOperators& operators, PrimitiveSet set);

  [[nodiscard]] std::string_view what() const override { return "trees"; }
  [[nodiscard]] std::string_view tag() const override { return "-trees"; }
  [[nodiscard]] std::size_t genes() const override { return 0; }
  // Ramped half-and-half of `count` trees (init.hpp), encoded.
  [[nodiscard]] std::vector<Genome> first(std::size_t count, Rng& rng) const override;
  // A genome that does not decode in the set, or breaks max_depth or max_size.
  [[nodiscard]] std::string misfit(std::span<const double> genome) const override;
  // Nothing: the primitive set is checked tree by tree (misfit), the operators' settings
  // may change between a run and its continuation, as a network's variation settings may.
  [[nodiscard]] std::vector<FixedSetting> fixed() const override { return {}; }

  // NSGA-II's variation of two winners into two children, in place: one uniform; below
  // `crossover`, a = crossover(a, b) and b = crossover(b, a) (subtree crossover, Koza's
  // internal bias); then each child, a first, goes through the GP's mutation mix (one
  // uniform and the operator's draws; most often no mutation at the GP's 5 % each).
  void cross_and_mutate(Genome& a, Genome& b, Rng& rng) const;

  // MAP-Elites' variation of one elite: exactly one of the GP's mutations, chosen with
  // probabilities proportional to subtree_mutation, point_mutation and hoist_mutation (one
  // uniform, then the operator's draws). A copy would only measure an elite again; with all
  // three at 0, it is a copy all the same (map_elites_problem refuses such settings).
  [[nodiscard]] Genome mutate_one(std::span<const double> parent, Rng& rng) const;

  // The three mutation probabilities summed: 0 when the settings never mutate.
  [[nodiscard]] double mutation_sum() const noexcept;

 private:
  TreeOperators ops_;
  PrimitiveSet set_;
};

// Bytes one encoded tree of at most max_size nodes holds.
[[nodiscard]] double encoded_tree_bytes(const TreeOperators& operators) noexcept;

// Why `algorithm` cannot vary the problem's trees (the experiment gives no GP settings), or
// "" (also for a network).
[[nodiscard]] std::string tree_problem(const evo::Problem& problem, std::string_view algorithm);

}  // namespace esc::genome::tree
