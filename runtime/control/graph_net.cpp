#include "runtime/control/graph_net.hpp"

#include <stdexcept>
#include <string>

#include "runtime/genome/graph/codec.hpp"

namespace esc::control {

namespace gg = genome::graph;

gg::Activation graph_activation(Activation a) noexcept {
  switch (a) {
    case Activation::Tanh: return gg::Activation::Tanh;
    case Activation::Sigmoid: return gg::Activation::Sigmoid;
    case Activation::Linear: break;
  }
  return gg::Activation::Linear;
}

namespace {

gg::Network network_of(std::span<const double> genome, std::size_t inputs, std::size_t outputs) {
  gg::Graph g;
  if (const std::string why = gg::decode(genome, g); !why.empty())
    throw std::invalid_argument("not a graph genome: " + why);
  const std::size_t in = gg::count_nodes(g, gg::NodeKind::Input);
  const std::size_t out = gg::count_nodes(g, gg::NodeKind::Output);
  if (in != inputs || out != outputs)
    throw std::invalid_argument("a graph genome of " + std::to_string(in) + " inputs and " + std::to_string(out) +
                                " outputs, the network has " + std::to_string(inputs) + " and " +
                                std::to_string(outputs));
  return gg::Network(g);
}

}  // namespace

std::string graph_genome_problem(const ControllerSpec& c, std::span<const double> genome) {
  try {
    (void)network_of(genome, c.mlp.inputs.size(), static_cast<std::size_t>(c.output_count()));
    return {};
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

GraphNet::GraphNet(const MlpSpec& spec, int outputs, std::span<const double> genome)
    : inputs_(spec.inputs),
      outputs_(static_cast<std::size_t>(outputs < 0 ? 0 : outputs)),
      net_(network_of(genome, spec.inputs.size(), outputs_)),
      in_(spec.inputs.size(), 0.0) {
  for (const expr::Slot s : inputs_)
    if (s >= expr::kFrameSize)
      throw std::invalid_argument("input slot " + std::to_string(s) + " lies outside the frame");
}

void GraphNet::rebind(std::span<const double> genome) { net_ = network_of(genome, inputs_.size(), outputs_); }

void GraphNet::forward(const expr::Frame& frame) noexcept {
  for (std::size_t i = 0; i < inputs_.size(); ++i) in_[i] = frame[inputs_[i]];
  // An output no enabled path reaches stays 0: a genome's own failure, not the controller's.
  (void)net_.step(in_);
}

}  // namespace esc::control
