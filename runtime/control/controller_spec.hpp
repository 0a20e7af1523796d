#pragma once
// What the compiler produces for a `controller` declaration: the network's shape and its
// head. The genome is the flat vector of the network's weights; genome_size() says how long.
#include <cstddef>
#include <string>
#include <vector>

#include "runtime/control/behavior.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::control {

enum class Activation { Tanh, Sigmoid, Linear };

// A multi-layer perceptron: inputs are frame slots, then hidden layers, then outputs.
// Each layer's weights are stored neuron by neuron, bias first, then one weight per input.
struct MlpSpec {
  std::vector<expr::Slot> inputs;
  std::vector<int> hidden;          // sizes of the hidden layers, may be empty
  Activation hidden_activation = Activation::Tanh;
};

// Classical head: two outputs in [-1, 1] (tanh) are the wheel commands.
// Symbolic head: outputs in [0, 1] (logistic). The first n (one per action) choose the
// action by argmax (first wins a tie); then each action's parameters follow in order
// (action 0's, then action 1's, ...), so n actions of one parameter give 2n outputs.
enum class Head { Classical, Symbolic };

struct ControllerSpec {
  std::string name;
  MlpSpec mlp;
  Head head = Head::Classical;
  std::vector<Behavior> actions;    // Symbolic head only

  [[nodiscard]] int output_count() const noexcept;
  [[nodiscard]] std::size_t genome_size() const noexcept;
  // "8-14-6" style architecture string for tables.
  [[nodiscard]] std::string architecture() const;
};

}  // namespace esc::control
