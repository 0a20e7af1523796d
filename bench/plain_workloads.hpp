#pragma once
// The paper's three benchmark workloads written as plain loops (no esc code): obstacle
// avoidance with the 8-14-6 symbolic controller, the energy experiment's Elman 17-5-2
// classical controller, and its Elman 17-5-4 symbolic supervisor over four behaviors. Each
// evaluates one genome as esc's Evaluator does (epochs from random start poses, the same
// step order, the same stop conditions) so that `esc bench` can divide esc's rate by theirs.
#include <cstdint>
#include <span>
#include <vector>

#include "bench/plain_network.hpp"
#include "bench/plain_world.hpp"

namespace esc::bench::plain {

struct Result {
  std::int64_t steps = 0;   // control steps simulated
  double fitness = 0.0;
};

// Epochs of `steps` ending at the first contact; fitness: the forward term.
class Obstacle {
 public:
  explicit Obstacle(const Setup& s) : world_(s) {}
  static constexpr std::size_t kGenomeSize = Network<8, 14, 6>::kWeights;
  Result evaluate(std::span<const double> genome, std::uint64_t seed);

 private:
  World world_;
  Network<8, 14, 6> net_;
};

// A recharge zone drawn at every epoch with a light above it, the accumulator, epochs of
// `steps` ending when it is empty; fitness: the forward term outside the zone. Inputs: 8 IR,
// 8 light, the accumulator's level.
class Energy {
 public:
  explicit Energy(const Setup& s) : world_(s) {}
  static constexpr std::size_t kGenomeSize = Network<17, 5, 2, true>::kWeights;
  Result evaluate(std::span<const double> genome, std::uint64_t seed);

 private:
  World world_;
  Network<17, 5, 2, true> net_;
};

// The energy workload driven by a supervisor: its Elman 17-5-4 network chooses at every step
// which of four symbolic behaviors runs (avoid 8-14-6 over IR, follow 16-6 over IR and
// light, stop 8-6 over IR, sweep 8-14-6 over IR); only the chosen one computes.
class Supervisor {
 public:
  // `behaviors`: the four behaviors' genomes, in that order. Throws std::invalid_argument
  // when they are not four of the sizes above.
  Supervisor(const Setup& s, std::vector<std::vector<double>> behaviors);
  static constexpr std::size_t kGenomeSize = Network<17, 5, 4, true>::kWeights;
  Result evaluate(std::span<const double> genome, std::uint64_t seed);

 private:
  World world_;
  Network<17, 5, 4, true> net_;
  Network<8, 14, 6> avoid_, sweep_;
  Network<16, 0, 6> follow_;
  Network<8, 0, 6> stop_;
  std::vector<std::vector<double>> genomes_;
};

}  // namespace esc::bench::plain
