#pragma once
// NSGA-II (Deb, Pratap, Agarwal & Meyarivan, "A fast and elitist multiobjective genetic
// algorithm: NSGA-II", IEEE TEC 6(2), 2002) over real genes in a box, as an ask/tell value
// type. Objectives are MINIMISED, as in the literature: a caller that maximises (esc's
// robots) passes their negations. docs/optimizers.md has the details and the validation
// against DEAP.
//
// One generation: N parents, each with its front (rank) and crowding distance, play binary
// crowded tournaments; the winners, in consecutive pairs, are crossed by SBX with probability
// `crossover` and each child is mutated (variation.hpp); tell() then keeps the N best of
// parents and children by rank and crowding (pareto/selection.hpp), whole fronts first.
//
// Where the paper, Deb's C code (revision 1.1.6) and DEAP (1.3, examples/ga/nsga2.py) differ:
// - Tournament. The paper compares by the crowded-comparison operator (rank, then crowding);
//   Deb's code and DEAP's selTournamentDCD by Pareto dominance between the two, then crowding,
//   then a coin. esc follows the paper, with the lower index as the last tie-break instead of
//   a coin (no draw, an order that never depends on sort stability). A point of a better
//   front that does not dominate its opponent thus wins here where the code might let it
//   lose on crowding. Who meets whom follows the code and DEAP: two random orders of the
//   parents, each point in exactly two tournaments.
// - Crossover and mutation are the code's and DEAP's (variation.hpp): SBX gene by gene with
//   probability 0.5, the bounded spread, the children's values assigned by a coin; every
//   child then mutated gene by gene with probability `mutation` (1/n by default), the bounded
//   polynomial mutation. The paper gives only the operators' names and the indices.
// - Crowding distances are those of the fronts of parents plus children (as in the code and
//   DEAP), not recomputed among the survivors; esc's sum is not divided by the number of
//   objectives (DEAP's is: the same order).
// - The survivors keep the order of parents then children (ascending index in the merged
//   set), not DEAP's front order; only the index tie-break of the tournament sees it.
//
// What the genes are is the Nsga2Genomes given (a Representation and a variation of two
// winners): a network's weights in a box with SBX and polynomial mutation, as above, by
// default; trees with the GP's crossover and mutations (genome/tree/tree_variation.hpp);
// NEAT networks with NEAT's (genome/graph/graph_variation.hpp). Ranking, tournaments and
// survival are the same code for all three.
//
// Random draws come from the Rng given, in a fixed order. start(Rng&) draws N x n uniforms
// (candidate by candidate, gene by gene) for the first generation. start(point) draws
// nothing: the point is candidate 0 of the first ask, unchanged, and that ask draws the other
// N - 1 uniformly. A later ask draws the tournaments (crowded_tournament_winners), then per
// pair of winners one uniform for the crossover, SBX's draws if crossed, and the mutation of
// the first child, then the second. Give ask() the generation's own stream, so a run resumed
// from save() draws what it would have drawn: no Rng state is stored.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/pareto/selection.hpp"
#include "runtime/genome/representation.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo {

struct Nsga2Settings {
  int population = 100;         // N, even: parents kept and children made each generation
  double crossover = 0.9;       // probability that a pair of winners is crossed (SBX)
  double eta_crossover = 20.0;  // SBX's distribution index: larger, children nearer their parents
  double eta_mutation = 20.0;   // polynomial mutation's distribution index
  double mutation = 0.0;        // probability that a gene mutates; 0: 1 / n
  double lower = -1.0;          // every gene lies in [lower, upper]
  double upper = 1.0;
};

inline constexpr int kNsga2MaxPopulation = 1'000'000;

// Throws std::invalid_argument naming the first setting out of range: population even in
// [2, 1e6]; crossover and mutation in [0, 1]; both etas finite and at least 0; lower below
// upper, both within +-1e6.
void check_nsga2_settings(const Nsga2Settings& settings);

// Bytes one NSGA-II over n genes and `objectives` objectives holds while a tell ranks parents
// and children together: parents, children and the children handed out (3 N rows of n, as
// the heap holds them: memory_peak.hpp); the objectives of parents and children and the
// caller's copy of the children's; the merged rows' headers; per point of parents plus
// children its rank, crowding distance, front and the sort's and the selection's indices
// (the non-dominated sort holds O(N): pareto/fronts.hpp); the saved state of the parents.
[[nodiscard]] double nsga2_memory_bytes(const Nsga2Settings& settings, std::size_t n, std::size_t objectives);

// What NSGA-II's genes are: the first candidates and the check of a stored one, and how two
// tournament winners become two children (in place, drawing from the Rng given); `begin`,
// when set, is shown the parents before a generation's children are bred from them (graph
// genomes number their new structure past the parents': graph_variation.hpp).
struct Nsga2Genomes {
  std::shared_ptr<const genome::Representation> representation;
  std::function<void(Genome&, Genome&, Rng&)> vary;
  std::function<void(std::span<const Genome>)> begin = {};
};

// n genes in the settings' box, varied by SBX and polynomial mutation (variation.hpp).
[[nodiscard]] Nsga2Genomes box_genomes(const Nsga2Settings& settings, std::size_t n);

class Nsga2 {
 public:
  // Throws std::invalid_argument for settings out of range (check_nsga2_settings) or n = 0.
  Nsga2(const Nsga2Settings& settings, std::size_t n);
  // Over other genes (trees): of `settings`, only the population is used.
  Nsga2(const Nsga2Settings& settings, Nsga2Genomes genomes);

  // Starts (again) from N points drawn uniformly in the box, or from a given point in it
  // (std::invalid_argument otherwise), candidate 0 of the first ask.
  void start(Rng& rng);
  void start(std::span<const double> point);

  // N candidates of n genes in [lower, upper]: the first population, then children of the
  // parents. std::logic_error before start().
  [[nodiscard]] std::vector<std::vector<double>> ask(Rng& rng);
  // The objectives (minimised) of the last ask's candidates, in their order, every one of
  // the same number, fixed by the first tell. The first tell makes them the parents; a
  // later one keeps the N best of parents and children. NaN objectives rank last.
  // std::logic_error without a pending ask, std::invalid_argument for another count.
  // Returns which survived, as indices into parents (as they were) then candidates: what a
  // caller keeping something per point (novelty's descriptors) keeps in step with.
  std::vector<std::size_t> tell(std::span<const std::vector<double>> objectives);
  // Replaces the parents' objectives before the next tell compares them with the candidates:
  // for a score that changes with time, as novelty does while its archive grows. The
  // tournaments already drawn are not redrawn. std::invalid_argument for another count.
  void rescore(std::span<const std::vector<double>> parents);

  // The parents after the last tell (empty before the first), their objectives, fronts
  // (0: non-dominated) and crowding distances, aligned.
  [[nodiscard]] const std::vector<std::vector<double>>& population() const noexcept { return parents_; }
  [[nodiscard]] const ObjectiveRows& objectives() const noexcept { return objectives_; }
  [[nodiscard]] const std::vector<std::size_t>& ranks() const noexcept { return ranking_.rank; }
  [[nodiscard]] const std::vector<double>& crowding() const noexcept { return ranking_.crowding; }
  // The parents of rank 0, ascending: the trade-offs found, what a run stores.
  [[nodiscard]] std::vector<std::size_t> first_front() const;

  [[nodiscard]] std::uint64_t generation() const noexcept { return generation_; }  // tells
  [[nodiscard]] std::size_t population_size() const noexcept { return static_cast<std::size_t>(s_.population); }
  [[nodiscard]] std::size_t dimension() const noexcept { return n_; }
  // The per-gene mutation probability in use (1 / n when the setting is 0).
  [[nodiscard]] double mutation_probability() const noexcept;
  [[nodiscard]] const genome::Representation& representation() const noexcept { return *g_.representation; }
  [[nodiscard]] const Nsga2Settings& settings() const noexcept { return s_; }

  // The whole state between generations (after start or tell; a pending ask is not part of
  // it). load() takes a state saved by an NSGA-II of the same n, population and box and
  // continues bit for bit; anything else (another size, truncated or longer bytes, genes
  // outside the box or not finite, a NaN or negative crowding distance) throws
  // std::invalid_argument and leaves this object unchanged. The variation settings are this
  // object's, so a run can be carried on with others. Over trees the format is
  // "esc-nsga2-trees" (n 0, no box; every tree checked against the primitive set and the
  // GP's limits), and a state of the other representation is refused by name.
  [[nodiscard]] StateBytes save() const;
  void load(std::span<const std::uint8_t> bytes);

 private:
  Nsga2Settings s_;
  Nsga2Genomes g_;
  std::size_t n_;
  bool started_ = false;
  std::uint64_t generation_ = 0;
  std::size_t objective_count_ = 0;       // fixed by the first tell
  std::vector<std::vector<double>> initial_;  // the first candidates: N, or a given point, until the first tell
  std::vector<std::vector<double>> parents_;
  ObjectiveRows objectives_;
  Ranking ranking_;
  std::vector<std::vector<double>> children_;  // the last ask's candidates
  bool asked_ = false;
};

}  // namespace esc::evo
