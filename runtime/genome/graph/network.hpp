#pragma once
// The network a graph genome builds (its phenotype), activated as NEAT C++'s
// Network::activate does: in one pass every non-sensor node sums weight x output over its
// enabled in-links, reading the outputs the previous pass left (so the update is
// synchronous and a recurrent link is simply read a pass late), then every node that has
// an active input (a sensor, or a node active in an earlier pass) applies its activation;
// a node not yet active outputs 0. (NEAT C++ reads the flags of the nodes listed before a
// node as set in the same pass: a deep output may turn on one pass later here.) One
// activation runs passes until every output is active (at least one, at most 19). Two ways
// to use it:
//   step(inputs)  one activation per control step, the state carried to the next (what the
//                 robot experiments do: NEAT C++'s maze and pole tasks call activate() once
//                 per step); reset() at an epoch's start clears it.
//   relax(inputs) for classification (the paper's XOR, xor_evaluate): one activation, then
//                 depth() + 1 more passes so a feed-forward net settles; reset() before
//                 each pattern.
// Nothing is allocated after construction.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

// NEAT C++'s slope: fsigmoid(x, 4.924273, 2.4621365), "1 / (1 + exp(-4.924273 x))".
inline constexpr double kNeatSigmoidSlope = 4.924273;
// NEAT C++'s activate() gives up when its try counter (abortcount) reaches 20: 19 passes.
inline constexpr int kMaxPasses = 19;

[[nodiscard]] double activate(Activation a, double x);

class Network {
 public:
  // Throws std::invalid_argument when misfit(g) finds something.
  explicit Network(const Graph& g);

  [[nodiscard]] std::size_t inputs() const noexcept { return inputs_; }
  [[nodiscard]] std::size_t outputs() const noexcept { return output_index_.size(); }
  // The longest path, in links, from a sensor to an output over enabled links, a cycle
  // counted at most once round (bounded by the node count): the passes a signal needs.
  [[nodiscard]] int depth() const noexcept { return depth_; }

  // Every node inactive, every output 0 (NEAT C++'s flush).
  void reset();
  // One activation on `inputs` (inputs() values); false when an output stayed inactive for
  // kMaxPasses passes (no enabled path reaches it), its value then 0.
  bool step(std::span<const double> inputs);
  // step(), then depth() + 1 more passes.
  bool relax(std::span<const double> inputs);
  [[nodiscard]] std::span<const double> output() const noexcept { return out_; }

 private:
  void load(std::span<const double> inputs);
  void pass();
  bool outputs_active() const;
  void read_outputs();

  std::size_t inputs_ = 0;
  std::size_t sensors_ = 0;                 // inputs then the bias: nodes [0, sensors_)
  std::vector<Activation> activation_;      // per node
  std::vector<std::size_t> first_in_;       // per node + 1: its in-links in [first_in_[k], first_in_[k+1])
  std::vector<std::size_t> source_;         // per in-link: the node it reads
  std::vector<double> weight_;              // per in-link
  std::vector<double> value_;               // per node: its output
  std::vector<double> sum_;
  std::vector<char> active_;
  std::vector<char> fed_;                   // scratch: gets an active input this pass
  std::vector<std::size_t> output_index_;
  std::vector<double> out_;
  int depth_ = 0;
};

}  // namespace esc::genome::graph
