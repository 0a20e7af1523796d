#pragma once
// An optimizer: what evolves the genomes of one run, whatever the algorithm (the paper's
// ES, GP, CMA-ES, ...), behind one ask/tell interface (as pycma's, or pagmo2's algorithm
// against its problem). The run loop (runtime/eval/run_job.cpp) asks for a
// generation's candidates, evaluates them anywhere (threads, MPI ranks, pooled with other
// runs), tells the optimizer what each measured, and stores its whole state after every
// generation, so that any optimizer is resumable after a kill and carried on to more
// generations without knowing how.
//
// Reproducibility is the optimizer's contract: every number it draws comes from a stream
// derived from the run's seed and the generation (Rng(seed, Stream::Init) for what it
// starts from, Rng(seed, Stream::Breed, g) for generation g's candidates), never from a
// stream that lives across generations. A state saved after generation g and loaded into a
// fresh optimizer of the same algorithm, settings and problem then asks for generation g + 1
// exactly what the uninterrupted one would.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/state_bytes.hpp"
#include "runtime/genome/graph/graph_space.hpp"
#include "runtime/genome/kind.hpp"
#include "runtime/genome/tree/tree_space.hpp"

namespace esc::evo {

// A candidate as the run loop, the store and the evaluator see it: a network's weights, or
// a tree encoded (genome/tree/codec.hpp). One form for both keeps the loop representation-blind.
using Genome = std::vector<double>;

// What evaluating one candidate measured. Objectives are maximised; one today (the fitness).
// Descriptors characterise the behavior (for diversity-seeking algorithms); empty when the
// experiment declares none.
struct Outcome {
  std::vector<double> objectives;
  std::vector<double> descriptors;
};

// A number an optimizer reports about its own state after a generation (CMA-ES's step size,
// ...), stored per generation beside the fitness statistics the run loop computes.
struct Metric {
  std::string name;
  double value = 0.0;
  friend bool operator==(const Metric&, const Metric&) = default;
};

// Which evaluation measured a candidate: the generation that asked for it and its index
// among that generation's candidates, from which the run loop derives its evaluation's seed
// (eval::evaluation_seed), so that a replay measures it again in its own evaluation.
// `generation` -1: not known (a state saved by an esc before optimizers kept it).
struct Measured {
  std::int64_t generation = -1;
  std::uint64_t candidate = 0;
  [[nodiscard]] bool known() const noexcept { return generation >= 0; }
  friend bool operator==(const Measured&, const Measured&) = default;
};

// One of what an optimizer keeps as its result beside the run's best: a point of NSGA-II's
// first front, an elite of MAP-Elites' archive, a behavior of novelty search's archive.
struct Member {
  // An archive's cell (novelty search: the order the behavior was added in); a front's
  // position in it.
  std::int64_t cell = 0;
  std::vector<double> objectives;    // maximised, as an Outcome's; empty where not kept
  std::vector<double> descriptors;   // empty where not kept
  Genome genome;                     // empty where not kept, and in a generation's changes
  Measured measured;                 // known where a genome is kept
  friend bool operator==(const Member&, const Member&) = default;
};

enum class MemberKind : std::uint8_t { Front, Archive };

struct Members {
  // A front is replaced whole by each generation; an archive changes cell by cell.
  MemberKind kind = MemberKind::Front;
  std::size_t objectives = 0;    // values each member keeps
  std::size_t descriptors = 0;
  // The first objectives when the optimizer computes them itself rather than the experiment
  // (novelty search's "novelty"); the experiment's own objectives follow, the fitness first.
  std::vector<std::string> own_objectives;
  std::vector<Member> members;
  // An archive's cells, for drawing it (filled when all members are asked for): a grid's bins
  // per descriptor, or a CVT's centroids (cells x descriptors, in unit coordinates, each
  // descriptor scaled by its range); both empty for a front or an archive of points.
  std::vector<std::size_t> bins;
  std::vector<double> centroids;

  // The cells of an archive drawn from bins or centroids; nullopt for a front, an archive of
  // points or members taken as changes only.
  [[nodiscard]] std::optional<std::size_t> cells() const {
    if (!bins.empty()) {
      std::size_t n = 1;
      for (const std::size_t b : bins) n *= b;
      return n;
    }
    if (!centroids.empty() && descriptors > 0) return centroids.size() / descriptors;
    return std::nullopt;
  }
};

// The range a value is declared to lie in; infinite ends where the script declares none.
struct Bounds {
  double lower = 0.0;
  double upper = 0.0;
  friend bool operator==(const Bounds&, const Bounds&) = default;
};

// What one run evolves: genomes of one kind (genome/kind.hpp), described by that kind's
// member: `genome_size` weights (a network), trees of `tree` (its primitive set, and the
// operators that vary them, the experiment's `evolve gp(...)`: what any algorithm that
// evolves trees varies them with; null when the experiment has none), or graphs of `graph`
// (a network whose topology evolves: its inputs and outputs; genome_size 0), from the run's
// `seed`; `start` is the genome a run that starts from a stored controller (`start from`)
// begins with, or null.
// `objectives` holds one range per objective of an Outcome, in its maximised form (a
// minimised objective declared in [0, 300] is [-300, 0] here); `descriptors` one per
// descriptor, as declared.
struct Problem {
  std::size_t genome_size = 0;
  genome::tree::TreeSpace tree;
  std::uint64_t seed = 0;
  const Genome* start = nullptr;
  std::vector<Bounds> objectives;
  std::vector<Bounds> descriptors;
  genome::graph::GraphSpace graph;   // last: brace lists written before graphs stay valid

  [[nodiscard]] genome::GenomeKind kind() const noexcept {
    if (tree.primitives != nullptr) return genome::GenomeKind::Tree;
    return graph.graphs() ? genome::GenomeKind::Graph : genome::GenomeKind::Vector;
  }
};

class Optimizer {
 public:
  virtual ~Optimizer() = default;

  // The candidates of generation `generation` (0 first, each asked once, in order). A run
  // that starts from a stored genome has it unchanged as candidate 0 of generation 0, so
  // that generation measures it in the new setting.
  [[nodiscard]] virtual std::vector<Genome> ask(int generation) = 0;
  // What the candidates of the last ask measured, in their order.
  virtual void tell(std::span<const Outcome> outcomes) = 0;
  // The optimizer's own numbers after the last tell; none by default.
  [[nodiscard]] virtual std::vector<Metric> metrics() const { return {}; }
  // What it keeps beside the best, or nothing (the ES, CMA-ES and GP keep a population, not
  // a result): with `changes`, what the last tell changed, without genomes (a front whole,
  // an archive's changed cells: what a run stores per generation); without, all it keeps
  // now, with genomes (what a replay picks a member from).
  [[nodiscard]] virtual std::optional<Members> members(bool /*changes*/) const { return std::nullopt; }
  // Why the search ended before its last generation ("" while it goes on): a run whose
  // optimizer has stopped ends there.
  [[nodiscard]] virtual std::string stopped() const { return {}; }

  // The whole state after the last tell (or as started), and back. load throws
  // std::invalid_argument when the bytes are not a state this optimizer could have written
  // (another size, another format, a tree outside its primitive set).
  [[nodiscard]] virtual StateBytes save() const = 0;
  virtual void load(std::span<const std::uint8_t> state) = 0;
};

}  // namespace esc::evo
