#include "runtime/control/controller_spec.hpp"

#include <string>

namespace esc::control {

int ControllerSpec::output_count() const noexcept {
  if (head == Head::Classical) return 2;
  std::size_t n = actions.size();
  for (const Behavior& a : actions) n += a.params.size();
  return static_cast<int>(n);
}

std::size_t ControllerSpec::genome_size() const noexcept {
  // Each layer out x (in + 1): one bias and one weight per input for every neuron.
  std::size_t total = 0;
  std::size_t in = mlp.inputs.size();
  for (int h : mlp.hidden) {
    const auto out = static_cast<std::size_t>(h < 0 ? 0 : h);
    total += out * (in + 1);
    in = out;
  }
  const int outputs = output_count();
  total += static_cast<std::size_t>(outputs < 0 ? 0 : outputs) * (in + 1);
  return total;
}

std::string ControllerSpec::architecture() const {
  std::string s = std::to_string(mlp.inputs.size());
  for (int h : mlp.hidden) s += '-' + std::to_string(h);
  s += '-' + std::to_string(output_count());
  return s;
}

}  // namespace esc::control
