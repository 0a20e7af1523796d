#include "runtime/control/mlp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace esc::control {

namespace {

template <class V>
void activate(V&& v, Activation a) noexcept {
  switch (a) {
    case Activation::Tanh:
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = std::tanh(v[i]);
      break;
    case Activation::Sigmoid:
      // exp(-x) may overflow to +inf for very negative x: 1 / inf is then exactly 0.
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = 1.0 / (1.0 + std::exp(-v[i]));
      break;
    case Activation::Linear: break;
  }
}

}  // namespace

Mlp::Mlp(const MlpSpec& spec, int outputs, Activation output_activation,
         std::span<const double> genome)
    : inputs_(spec.inputs) {
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

  layers_.reserve(spec.hidden.size() + 1);
  buffers_.reserve(spec.hidden.size() + 2);
  auto in = static_cast<Eigen::Index>(spec.inputs.size());
  if (elman && spec.hidden[0] >= 1) context_ = spec.hidden[0];
  buffers_.emplace_back(in + 1 + context_);
  std::size_t offset = 0;
  // `extra`: columns beyond [1; inputs], the context units of an Elman hidden layer.
  auto add_layer = [&](Eigen::Index out, Activation act, Eigen::Index extra) {
    layers_.push_back({out, in + 1 + extra, offset, act});
    offset += static_cast<std::size_t>(out * (in + 1 + extra));
    buffers_.emplace_back(out + 1);
    in = out;
  };
  for (std::size_t l = 0; l < spec.hidden.size(); ++l) {
    if (spec.hidden[l] < 1)
      throw std::invalid_argument("hidden layer " + std::to_string(l) + " has " +
                                  std::to_string(spec.hidden[l]) + " neurons; it needs at least 1");
    add_layer(spec.hidden[l], spec.hidden_activation, l == 0 ? context_ : 0);
  }
  add_layer(outputs, output_activation, 0);
  for (Eigen::VectorXd& b : buffers_) {
    b.setZero();
    b[0] = 1.0;  // the bias input, never overwritten
  }
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
  if (context_ > 0) buffers_[0].tail(context_).setZero();
}

std::span<const double> Mlp::forward(const expr::Frame& frame) noexcept {
  Eigen::VectorXd& x = buffers_.front();
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    x[static_cast<Eigen::Index>(i) + 1] = frame[inputs_[i]];
  for (std::size_t l = 0; l < layers_.size(); ++l) {
    const Layer& L = layers_[l];
    const RowMajorMap w(weights_ + L.offset, L.rows, L.cols);
    auto out = buffers_[l + 1].tail(L.rows);
    out.noalias() = w * buffers_[l];
    activate(out, L.activation);
  }
  // Elman: this step's hidden activations are the next step's context (layer 0 has run,
  // so overwriting its input buffer is safe).
  if (context_ > 0) buffers_[0].tail(context_) = buffers_[1].tail(context_);
  return {buffers_.back().data() + 1, output_count_};
}

}  // namespace esc::control
