#pragma once
// The network inside a `neat(...)` controller: a graph genome (runtime/genome/graph, NEAT's)
// decoded and built into a genome::graph::Network, activated once per control step as NEAT
// C++'s robot tasks activate theirs (Network::step: the state carries over, so a net of
// depth d answers a changed input d - 1 steps late), reset at each epoch. The output nodes
// apply their own activation, the one the head wants (the optimizer gives the minimal
// start's outputs output_activation(head)), so output(i) is already what the head reads.
// Building and rebind() decode and allocate; forward() does not.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "runtime/control/controller_spec.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/network.hpp"

namespace esc::control {

// The graph genome's activation for a controller activation.
[[nodiscard]] genome::graph::Activation graph_activation(Activation a) noexcept;

// Why `genome` cannot be `neat(...)` controller c's ("" when it can): not a graph genome, or
// one of other inputs or outputs. What a stored genome is checked with before it is run.
[[nodiscard]] std::string graph_genome_problem(const ControllerSpec& c, std::span<const double> genome);

class GraphNet {
 public:
  // `spec` must outlive the network (its input list is referenced). Throws
  // std::invalid_argument when `genome` is not a graph genome of spec.inputs.size() inputs
  // and `outputs` outputs.
  GraphNet(const MlpSpec& spec, int outputs, std::span<const double> genome);

  // Builds the network of another graph genome of the same inputs and outputs (allocates).
  void rebind(std::span<const double> genome);
  void reset() noexcept { net_.reset(); }
  void forward(const expr::Frame& frame) noexcept;
  [[nodiscard]] double output(std::size_t i) const noexcept { return net_.output()[i]; }

 private:
  std::span<const expr::Slot> inputs_;
  std::size_t outputs_;
  genome::graph::Network net_;
  std::vector<double> in_;
};

}  // namespace esc::control
