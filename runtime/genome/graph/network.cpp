#include "runtime/genome/graph/network.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace esc::genome::graph {

double activate(Activation a, double x) {
  switch (a) {
    case Activation::NeatSigmoid: return 1.0 / (1.0 + std::exp(-kNeatSigmoidSlope * x));
    case Activation::Sigmoid: return 1.0 / (1.0 + std::exp(-x));
    case Activation::Tanh: return std::tanh(x);
    case Activation::Linear: return x;
  }
  return x;
}

Network::Network(const Graph& g) {
  if (const std::string why = misfit(g); !why.empty()) throw std::invalid_argument("graph genome: " + why);
  const std::size_t n = g.nodes.size();
  inputs_ = count_nodes(g, NodeKind::Input);
  sensors_ = sensor_count(g);
  activation_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    activation_[k] = g.nodes[k].activation;
    if (g.nodes[k].kind == NodeKind::Output) output_index_.push_back(k);
  }
  // In-links grouped by their output node, in innovation order within a node.
  first_in_.assign(n + 1, 0);
  for (const LinkGene& l : g.links)
    if (l.enabled) ++first_in_[node_index(g, l.out) + 1];
  for (std::size_t k = 0; k < n; ++k) first_in_[k + 1] += first_in_[k];
  source_.resize(first_in_[n]);
  weight_.resize(first_in_[n]);
  std::vector<std::size_t> fill(first_in_.begin(), first_in_.end() - 1);
  for (const LinkGene& l : g.links) {
    if (!l.enabled) continue;
    const std::size_t at = fill[node_index(g, l.out)]++;
    source_[at] = node_index(g, l.in);
    weight_[at] = l.weight;
  }
  value_.assign(n, 0.0);
  sum_.assign(n, 0.0);
  active_.assign(n, 0);
  fed_.assign(n, 0);
  out_.assign(output_index_.size(), 0.0);

  // Longest paths by at most n rounds of relaxation: a cycle lengthens them until the cap.
  const int cap = static_cast<int>(n);
  std::vector<int> reach(n, -1);
  for (std::size_t k = 0; k < sensors_; ++k) reach[k] = 0;
  for (std::size_t round = 0; round < n; ++round) {
    bool changed = false;
    for (std::size_t k = sensors_; k < n; ++k)
      for (std::size_t e = first_in_[k]; e < first_in_[k + 1]; ++e)
        if (reach[source_[e]] >= 0 && reach[source_[e]] + 1 > reach[k] && reach[source_[e]] < cap) {
          reach[k] = reach[source_[e]] + 1;
          changed = true;
        }
    if (!changed) break;
  }
  for (const std::size_t k : output_index_) depth_ = std::max(depth_, reach[k]);
}

void Network::reset() {
  std::fill(value_.begin(), value_.end(), 0.0);
  std::fill(active_.begin(), active_.end(), 0);
  std::fill(out_.begin(), out_.end(), 0.0);
}

void Network::load(std::span<const double> inputs) {
  if (inputs.size() != inputs_) throw std::invalid_argument("graph network: wrong number of inputs");
  for (std::size_t k = 0; k < inputs_; ++k) value_[k] = inputs[k];
  value_[inputs_] = 1.0;   // the bias
  for (std::size_t k = 0; k < sensors_; ++k) active_[k] = 1;
}

void Network::pass() {
  const std::size_t n = value_.size();
  for (std::size_t k = sensors_; k < n; ++k) {
    double s = 0.0;
    char fed = 0;
    for (std::size_t e = first_in_[k]; e < first_in_[k + 1]; ++e) {
      s += weight_[e] * value_[source_[e]];
      fed = static_cast<char>(fed | active_[source_[e]]);
    }
    sum_[k] = s;
    fed_[k] = fed;
  }
  for (std::size_t k = sensors_; k < n; ++k) {
    if (fed_[k] == 0) continue;
    value_[k] = activate(activation_[k], sum_[k]);
    active_[k] = 1;
  }
}

bool Network::outputs_active() const {
  return std::all_of(output_index_.begin(), output_index_.end(), [&](std::size_t k) { return active_[k] != 0; });
}

void Network::read_outputs() {
  for (std::size_t o = 0; o < output_index_.size(); ++o) out_[o] = value_[output_index_[o]];
}

bool Network::step(std::span<const double> inputs) {
  load(inputs);
  int passes = 0;
  do {
    pass();
    ++passes;
  } while (!outputs_active() && passes < kMaxPasses);
  read_outputs();
  return outputs_active();
}

bool Network::relax(std::span<const double> inputs) {
  const bool ok = step(inputs);
  for (int r = 0; r <= depth_; ++r) pass();
  read_outputs();
  return ok;
}

}  // namespace esc::genome::graph
