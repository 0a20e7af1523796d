#include "runtime/control/mlp.hpp"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <stdexcept>
#include <string>

namespace esc::control {

namespace {

// The weighted sums w . [1; x] of `Rows` neighbouring neurons (rows of `cols` columns from
// `w`), each summed in a fixed order: even and odd columns in two running sums, added, then
// an odd last column. This is the order of Eigen 3.4's row-major matrix-vector product with
// two-double packets (SSE2), which computed every result before this loop replaced it
// (docs/decisions.md, "Networks"): the same doubles, without Eigen's blocking and zeroing
// around a 9- or 15-column product. Several rows at once share the loads of x; SSE2 where the
// target has it (every x86-64), the same sums in scalar code elsewhere. Fixed here, the order
// no longer depends on the packet width Eigen picks for the build's target.
template <std::size_t Rows>
inline void neuron_sums(const double* w, const double* x, std::size_t cols, double* out) noexcept {
#if defined(__SSE2__)
  // Lane 0 holds the even columns' sum, lane 1 the odd columns'.
  __m128d acc[Rows];
  for (std::size_t r = 0; r < Rows; ++r) acc[r] = _mm_setzero_pd();
  std::size_t j = 0;
  for (; j + 2 <= cols; j += 2) {
    const __m128d xj = _mm_loadu_pd(x + j);
    for (std::size_t r = 0; r < Rows; ++r) acc[r] = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(w + r * cols + j), xj), acc[r]);
  }
  for (std::size_t r = 0; r < Rows; ++r) {
    double sum = _mm_cvtsd_f64(_mm_add_sd(acc[r], _mm_unpackhi_pd(acc[r], acc[r])));
    if (j < cols) sum += w[r * cols + j] * x[j];
    out[r] = sum;
  }
#else
  for (std::size_t r = 0; r < Rows; ++r) {
    const double* row = w + r * cols;
    double even = 0.0;
    double odd = 0.0;
    std::size_t j = 0;
    for (; j + 2 <= cols; j += 2) {
      even += row[j] * x[j];
      odd += row[j + 1] * x[j + 1];
    }
    double sum = even + odd;
    if (j < cols) sum += row[j] * x[j];
    out[r] = sum;
  }
#endif
}

// One layer's sums into out[0 .. rows), four neurons at a time.
inline void layer_sums(const double* w, const double* x, std::size_t rows, std::size_t cols, double* out) noexcept {
  std::size_t r = 0;
  for (; r + 4 <= rows; r += 4) neuron_sums<4>(w + r * cols, x, cols, out + r);
  if (r + 2 <= rows) {
    neuron_sums<2>(w + r * cols, x, cols, out + r);
    r += 2;
  }
  if (r < rows) neuron_sums<1>(w + r * cols, x, cols, out + r);
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
    layer_sums(w, x, L.rows, L.cols, out);
    if (L.activation != Activation::Linear)
      for (std::size_t r = 0; r < L.rows; ++r) out[r] = activate(out[r], L.activation);
  }
  // Elman: this step's hidden activations are the next step's context (layer 0 has run,
  // so overwriting its input block is safe).
  if (context_ > 0) std::copy_n(v + layers_.front().out, context_, v + 1 + inputs_.size());
}

}  // namespace esc::control
