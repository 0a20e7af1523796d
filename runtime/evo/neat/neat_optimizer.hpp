#pragma once
// NEAT (neat.hpp) as an Optimizer: generation 0 is the first population, drawn from
// Rng(seed, Init); generation g is bred from g - 1 with Rng(seed, Breed, g) alone. Each
// candidate is a graph genome in its flat form (genome/graph/codec.hpp). Its metrics are
// the species count, the mean hidden nodes and enabled links of the generation told, and
// the compatibility threshold; scored by novelty, also the archive's size and threshold,
// and its members are the archive's behaviors. NeatAlgorithm, below, is what the registry
// holds of it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/evo/neat/neat_settings.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

// What one run of NEAT evolves: networks of `inputs` inputs and `outputs` outputs (a bias
// is added), from `seed`; `start`, when not null, a graph genome every run begins from;
// the minimal start's output nodes take `output_activation` when given (a controller's
// head's), else the settings' activation; `descriptors`, the declared ranges of the
// behavior descriptors that score novelty measures (NeatScore::Novelty).
struct NeatProblem {
  std::size_t inputs = 0;
  std::size_t outputs = 0;
  std::uint64_t seed = 0;
  const Genome* start = nullptr;
  std::optional<genome::graph::Activation> output_activation = std::nullopt;
  std::vector<Bounds> descriptors = {};
};

// Throws std::invalid_argument on impossible settings or a start that is not a graph genome
// of that many inputs and outputs.
[[nodiscard]] std::unique_ptr<Optimizer> make_neat(const NeatSettings& settings, const NeatProblem& problem);

// Candidates per generation.
[[nodiscard]] std::size_t neat_population(const NeatSettings& settings);

// What one run's NEAT holds at its peak, while breeding: two populations of graphs (the
// parents and the children), their flat copies handed out and the saved state's writer
// (state_bytes.hpp, grown by doubling), each genome counted at twice
// the minimal start's links and its nodes plus one hidden node per output (a net that has
// grown; XOR's solutions have 2 to 3 times the start's links).
[[nodiscard]] MemoryPeak neat_memory_peak(const NeatSettings& settings, std::size_t inputs, std::size_t outputs);

// The same four over a run's Problem (its `graph`), as the algorithm registry calls them: a
// problem that evolves no graphs is refused (make_neat_run throws, neat_run_problem says so).
[[nodiscard]] std::unique_ptr<Optimizer> make_neat_run(const NeatSettings& settings, const Problem& problem);
[[nodiscard]] std::size_t neat_run_population(const NeatSettings& settings, const Problem& problem);
[[nodiscard]] MemoryPeak neat_run_memory_peak(const NeatSettings& settings, const Problem& problem);
[[nodiscard]] std::string neat_run_problem(const NeatSettings& settings, const Problem& problem);

// NEAT as the registry describes an algorithm (registry.hpp).
struct NeatAlgorithm {
  using Settings = NeatSettings;
  std::string_view name = "neat";
  std::string_view what = "NEAT";
  genome::GenomeKinds kinds{genome::GenomeKind::Graph};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_neat_run(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return neat_run_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return neat_run_memory_peak(s, p);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return neat_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return neat_run_problem(s, p); }
};

}  // namespace esc::evo
