#include "runtime/control/mlp.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace esc::control {

namespace {

// One neuron's weighted sum w . [1; x] over `cols` columns, summed in a fixed order: even
// and odd columns in two running sums, added, then an odd last column. This is the order of
// Eigen 3.4's row-major matrix-vector product with two-double packets (SSE2), which computed
// every result before this loop replaced it (docs/decisions.md, "Networks"): the same
// doubles, without Eigen's blocking and zeroing around a 9- or 15-column product. Fixed here,
// it no longer depends on the packet width Eigen picks for the build's target.
inline double neuron_sum(const double* w, const double* x, std::size_t cols) noexcept {
  double even = 0.0;
  double odd = 0.0;
  std::size_t j = 0;
  for (; j + 2 <= cols; j += 2) {
    even += w[j] * x[j];
    odd += w[j + 1] * x[j + 1];
  }
  double sum = even + odd;
  if (j < cols) sum += w[j] * x[j];
  return sum;
}

}  // namespace

Mlp::Mlp(const MlpSpec& spec, int outputs, Activation output_activation,
         std::span<const double> genome)
    : inputs_(spec.inputs), output_activation_(output_activation) {
  for (expr::Slot s : spec.inputs)
    if (s >= expr::kFrameSize)
      throw std::invalid_argument("network input slot " + std::to_string(s) +
                                  " is outside the frame (size " +
                                  std::to_string(expr::kFrameSize) + ")");
  if (outputs < 1) throw std::invalid_argument("network needs at least one output");
  const bool elman = spec.kind == NetworkKind::Elman;
  if (elman && spec.hidden.size() != 1)
    throw std::invalid_argument("an Elman network needs exactly one hidden layer, got " +
                                std::to_string(spec.hidden.size()));
  for (std::size_t l = 0; l < spec.hidden.size(); ++l)
    if (spec.hidden[l] < 1)
      throw std::invalid_argument("hidden layer " + std::to_string(l) + " has " +
                                  std::to_string(spec.hidden[l]) + " neurons; it needs at least 1");

  if (elman) context_ = static_cast<std::size_t>(spec.hidden[0]);
  std::size_t in = spec.inputs.size();
  std::size_t block = 0;                 // the current layer's input block
  std::size_t size = 1 + in + context_;  // values_ so far
  std::size_t offset = 0;
  layers_.reserve(spec.hidden.size() + 1);
  // `extra`: columns beyond [1; inputs], the context units of an Elman hidden layer.
  const auto add_layer = [&](std::size_t rows, Activation act, std::size_t extra, bool last) {
    const std::size_t cols = in + 1 + extra;
    const std::size_t first = last ? size : size + 1;  // a hidden block opens with its 1.0
    layers_.push_back({rows, cols, offset, block, first, act});
    offset += rows * cols;
    block = size;
    size = first + rows;
    in = rows;
  };
  for (std::size_t l = 0; l < spec.hidden.size(); ++l)
    add_layer(static_cast<std::size_t>(spec.hidden[l]), spec.hidden_activation, l == 0 ? context_ : 0, false);
  add_layer(static_cast<std::size_t>(outputs), Activation::Linear, 0, true);
  output_first_ = layers_.back().out;
  values_.assign(size, 0.0);
  for (const Layer& L : layers_) values_[L.in] = 1.0;  // the bias inputs, never overwritten
  weight_count_ = offset;
  output_count_ = static_cast<std::size_t>(outputs);
  rebind(genome);
}

void Mlp::rebind(std::span<const double> genome) {
  if (genome.size() != weight_count_)
    throw std::invalid_argument("network needs " + std::to_string(weight_count_) +
                                " weights, genome has " + std::to_string(genome.size()));
  weights_ = genome.data();
}

void Mlp::reset() noexcept {
  std::fill_n(values_.begin() + static_cast<std::ptrdiff_t>(1 + inputs_.size()), context_, 0.0);
}

void Mlp::forward(const expr::Frame& frame) noexcept {
  double* v = values_.data();
  for (std::size_t i = 0; i < inputs_.size(); ++i) v[1 + i] = frame[inputs_[i]];
  for (const Layer& L : layers_) {
    const double* w = weights_ + L.weights;
    const double* x = v + L.in;
    double* out = v + L.out;
    for (std::size_t r = 0; r < L.rows; ++r, w += L.cols) out[r] = activate(neuron_sum(w, x, L.cols), L.activation);
  }
  // Elman: this step's hidden activations are the next step's context (layer 0 has run,
  // so overwriting its input block is safe).
  if (context_ > 0) std::copy_n(v + layers_.front().out, context_, v + 1 + inputs_.size());
}

}  // namespace esc::control
