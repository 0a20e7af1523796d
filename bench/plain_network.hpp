#pragma once
// The plain reference's networks: an MLP or an Elman network of fixed sizes in Eigen, weights
// read from the genome in esc's layout (each neuron's bias, then its input weights, then an
// Elman neuron's context weights), tanh hidden units, tanh or logistic outputs. What a
// hand-written controller of one of the paper's sizes costs: one small matrix-vector product
// per layer, evaluated coefficient by coefficient at these sizes (lazyProduct: no call into
// Eigen's general product kernel), and the activations (std::tanh, std::exp).
#include <cmath>

#include <Eigen/Core>

namespace esc::bench::plain {

template <int Rows, int Cols>
using Weights = Eigen::Map<const Eigen::Matrix<double, Rows, Cols, Eigen::RowMajor>>;

template <int N>
using Vector = Eigen::Matrix<double, N, 1>;

template <int N>
Vector<N> logistic(const Vector<N>& sums) {
  return sums.unaryExpr([](double v) { return 1 / (1 + std::exp(-v)); });
}

// In inputs, Hidden tanh units (none when 0), Out outputs; `Elman`: the hidden layer also
// reads its own last activations (zero after reset()).
template <int In, int Hidden, int Out, bool Elman = false>
class Network {
 public:
  static constexpr int kContext = Elman ? Hidden : 0;
  static constexpr int kWeights = Hidden > 0 ? Hidden * (1 + In + kContext) + Out * (1 + Hidden) : Out * (1 + In);

  void reset() { context_.setZero(); }

  // The outputs' weighted sums, to be activated by the caller.
  Vector<Out> sums(const double* genome, const double* inputs) {
    Vector<1 + In + kContext> x;
    x[0] = 1;
    for (int i = 0; i < In; ++i) x[1 + i] = inputs[i];
    if constexpr (Hidden == 0) {
      return Weights<Out, 1 + In>(genome).lazyProduct(x);
    } else {
      if constexpr (Elman) x.template tail<Hidden>() = context_;
      Vector<1 + Hidden> h;
      h[0] = 1;
      h.template tail<Hidden>() = Weights<Hidden, 1 + In + kContext>(genome).lazyProduct(x).array().tanh();
      if constexpr (Elman) context_ = h.template tail<Hidden>();
      return Weights<Out, 1 + Hidden>(genome + Hidden * (1 + In + kContext)).lazyProduct(h);
    }
  }

 private:
  Vector<Elman ? Hidden : 1> context_ = Vector<Elman ? Hidden : 1>::Zero();
};

// A symbolic head over FORWARD, LEFT and RIGHT (logistic outputs): the first of the largest
// three outputs chooses the action, its parameter p (output 3 + action) its speed.
inline void symbolic_action(const Vector<6>& out, double& left, double& right) {
  int a = 0;
  for (int i = 1; i < 3; ++i)
    if (out[i] > out[a]) a = i;
  const double p = out[3 + a];
  left = a == 1 ? -p : p;
  right = a == 2 ? -p : p;
}

}  // namespace esc::bench::plain
