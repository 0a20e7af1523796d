#pragma once
// The network inside a controller: a multi-layer perceptron, or an Elman network, bound
// to a slice of a genome. Weights are not copied: layer l reads its rows straight from the
// genome, row-major out x (in + 1), bias in column 0. All activations live in one flat
// buffer, each layer's input block starting with a constant 1.0, so a neuron is one dot
// product of its genome row with [1; x]. The buffer is sized in the constructor; forward()
// does not allocate.
//
// forward() leaves the output layer's weighted sums un-activated: the head activates only
// the outputs it reads (a symbolic head reads the chosen action's parameters, never the
// others'), and output(i) gives the same value whenever it is asked.
//
// Elman: the input block is [1; x_t; h_{t-1}] (the context units sit after the inputs),
// so the recurrent hidden layer is still one row per neuron over 1 + n + h columns, exactly
// the genome layout (bias, input weights, context weights). After each forward() the new
// hidden activations are copied into the context units; reset() zeroes them.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/control/controller_spec.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::control {

[[nodiscard]] inline double activate(double x, Activation a) noexcept {
  switch (a) {
    case Activation::Tanh: return std::tanh(x);
    // exp(-x) may overflow to +inf for very negative x: 1 / inf is then exactly 0.
    case Activation::Sigmoid: return 1.0 / (1.0 + std::exp(-x));
    case Activation::Linear: break;
  }
  return x;
}

class Mlp {
 public:
  // `spec` must outlive the network (its input list is referenced, not copied).
  // Throws std::invalid_argument if a hidden layer is empty, an Elman network does not
  // have exactly one hidden layer, an input slot lies outside the frame, or `genome` does
  // not hold exactly weight_count() values.
  Mlp(const MlpSpec& spec, int outputs, Activation output_activation,
      std::span<const double> genome);

  // Points the network at another genome of the same size (no allocation).
  void rebind(std::span<const double> genome);

  // Zeroes the Elman context units (the start of an epoch); a feed-forward network has
  // no state.
  void reset() noexcept;

  // Reads the inputs from `frame` and runs every layer; the output layer's sums stay
  // un-activated until output(i) is asked.
  void forward(const expr::Frame& frame) noexcept;

  // Output i of the last forward(), activated.
  [[nodiscard]] double output(std::size_t i) const noexcept {
    return activate(values_[output_first_ + i], output_activation_);
  }

  [[nodiscard]] std::size_t weight_count() const noexcept { return weight_count_; }
  [[nodiscard]] std::size_t output_count() const noexcept { return output_count_; }

 private:
  struct Layer {
    std::size_t rows;      // neurons
    std::size_t cols;      // inputs + 1 (bias)
    std::size_t weights;   // first weight of the layer in the genome
    std::size_t in;        // first value of its input block [1; x] in values_
    std::size_t out;       // first value of its neurons in values_
    Activation activation; // Linear for the output layer (the head activates)
  };

  std::span<const expr::Slot> inputs_;
  std::vector<Layer> layers_;
  // [1, inputs (, context)] [1, hidden layer 1] ... [1, last hidden layer] [output sums]
  std::vector<double> values_;
  std::size_t context_ = 0;   // Elman: hidden size, the tail of the input block; else 0
  std::size_t output_first_ = 0;
  Activation output_activation_;
  const double* weights_ = nullptr;
  std::size_t weight_count_ = 0;
  std::size_t output_count_ = 0;
};

}  // namespace esc::control
