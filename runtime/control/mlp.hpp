#pragma once
// The network inside a controller: a multi-layer perceptron, or an Elman network, bound
// to a slice of a genome. Weights are not copied: each layer is an Eigen::Map over the
// genome, row-major out x (in + 1), bias in column 0. Every activation buffer keeps a
// constant 1.0 at index 0, so a layer is one matrix-vector product W * [1; x] written
// straight into the next buffer. All buffers are sized in the constructor; forward() does
// not allocate.
//
// Elman: the input buffer is [1; x_t; h_{t-1}] (the context units sit after the inputs),
// so the recurrent hidden layer is still one product with its h x (1 + n + h) matrix, whose
// rows are exactly the genome layout (bias, input weights, context weights). After each
// forward() the new hidden activations are copied into the context units; reset() zeroes
// them.
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "runtime/control/controller_spec.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::control {

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

  // Reads the inputs from `frame` and returns the outputs, valid until the next call.
  std::span<const double> forward(const expr::Frame& frame) noexcept;

  [[nodiscard]] std::size_t weight_count() const noexcept { return weight_count_; }
  [[nodiscard]] std::size_t output_count() const noexcept { return output_count_; }

 private:
  struct Layer {
    Eigen::Index rows;    // neurons
    Eigen::Index cols;    // inputs + 1 (bias)
    std::size_t offset;   // first weight of the layer in the genome
    Activation activation;
  };
  using RowMajorMap =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

  std::span<const expr::Slot> inputs_;
  std::vector<Layer> layers_;
  // buffers_[0] = [1, inputs] (Elman: [1, inputs, context]), buffers_[l+1] = [1, layer l]
  std::vector<Eigen::VectorXd> buffers_;
  Eigen::Index context_ = 0;  // Elman: hidden size, the tail of buffers_[0]; else 0
  const double* weights_ = nullptr;
  std::size_t weight_count_ = 0;
  std::size_t output_count_ = 0;
};

}  // namespace esc::control
