#include "runtime/control/controller_spec.hpp"

#include <string>

#include "runtime/control/graph_architecture.hpp"

namespace esc::control {

int ControllerSpec::output_count() const noexcept {
  switch (head) {
    case Head::Classical: return 2;
    case Head::Supervisor: return static_cast<int>(behaviors.size());
    case Head::Symbolic: break;
  }
  std::size_t n = actions.size();
  for (const Behavior& a : actions) n += a.params.size();
  return static_cast<int>(n);
}

std::size_t ControllerSpec::network_offset(std::size_t k) const noexcept {
  std::size_t offset = 0;
  for (std::size_t i = 0; i < k && i < networks.size(); ++i) offset += networks[i].genome_size();
  return offset;
}

std::size_t ControllerSpec::genome_size() const noexcept {
  if (per_body()) return network_offset(networks.size());
  if (is_tree() || is_graph()) return 0;
  // Each layer out x (in + 1): one bias and one weight per input for every neuron; an
  // Elman hidden layer also takes its own previous activations as inputs, out x (in + 1 + out).
  const bool elman = mlp.kind == NetworkKind::Elman;
  std::size_t total = 0;
  std::size_t in = mlp.inputs.size();
  for (int h : mlp.hidden) {
    const auto out = static_cast<std::size_t>(h < 0 ? 0 : h);
    total += out * (in + 1 + (elman ? out : 0));
    in = out;
  }
  const int outputs = output_count();
  total += static_cast<std::size_t>(outputs < 0 ? 0 : outputs) * (in + 1);
  return total;
}

const char* ControllerSpec::head_name() const noexcept {
  if (is_tree()) return "tree";
  switch (head) {
    case Head::Classical: return "classical";
    case Head::Symbolic: return "symbolic";
    case Head::Supervisor: return "supervisor";
  }
  return "unknown";
}

std::string ControllerSpec::architecture() const {
  if (is_tree())
    return head == Head::Classical ? "tree wheels" : head == Head::Symbolic ? "tree actions" : "tree behaviors";
  if (per_body()) {
    std::string all;
    for (std::size_t k = 0; k < networks.size(); ++k)
      all += (all.empty() ? "" : " / ") + (k < network_bodies.size() ? network_bodies[k] + ' ' : std::string()) +
             networks[k].architecture();
    return all;
  }
  std::string s = std::to_string(mlp.inputs.size());
  if (is_graph()) return s + kGraphArchitectureMark + std::to_string(output_count());
  for (int h : mlp.hidden) {
    s += '-' + std::to_string(h);
    if (mlp.kind == NetworkKind::Elman) s += 'r';
  }
  s += '-' + std::to_string(output_count());
  return s;
}

std::vector<std::string> ControllerSpec::choice_names() const {
  std::vector<std::string> names;
  if (head == Head::Symbolic)
    for (const Behavior& a : actions) names.push_back(a.name);
  if (head == Head::Supervisor)
    for (const SupervisedBehavior& b : behaviors) names.push_back(b.name);
  return names;
}

}  // namespace esc::control
