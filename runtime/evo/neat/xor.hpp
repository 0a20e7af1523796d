#pragma once
// The NEAT paper's first experiment (Stanley & Miikkulainen 2002, section 4.1), XOR, as a
// task without a robot, evaluated as NEAT C++'s xor_evaluate does: each of the four
// patterns (bias 1 and two inputs in {0, 1}) is fed to a freshly reset network that is
// relaxed (one activation, then depth + 1 passes); fitness (4 - sum |error|)^2; solved when
// every output is on the right side of 0.5. A network whose output never turns on scores
// 0.001, as there.
#include <cstdint>
#include <vector>

#include "runtime/evo/neat/neat_settings.hpp"
#include "runtime/genome/graph/graph.hpp"

namespace esc::evo {

struct XorScore {
  double fitness = 0.0;
  bool solved = false;
};

[[nodiscard]] XorScore score_xor(const genome::graph::Graph& g);

// One run of NEAT on XOR through the Optimizer interface, until a network solves it or
// `max_generations` generations have been evaluated.
struct XorRun {
  std::uint64_t seed = 0;
  bool solved = false;
  int generations = 0;             // evaluated, the solving one included
  std::uint64_t evaluations = 0;   // networks evaluated up to and including the first solution
  std::size_t hidden_nodes = 0;    // of the first solution
  std::size_t enabled_links = 0;
};

[[nodiscard]] XorRun solve_xor(const NeatSettings& settings, std::uint64_t seed, int max_generations);

}  // namespace esc::evo
