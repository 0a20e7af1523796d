#pragma once
// What marks a NEAT network's architecture string ("8-neat-2", ControllerSpec::architecture):
// how stored results, which keep the string and not the spec, tell a graph genome from a
// network's weights (the topology export, the report's network figures).
#include <string_view>

namespace esc::control {

inline constexpr const char* kGraphArchitectureMark = "-neat-";

// Whether a stored controller of this architecture is a NEAT network (its genomes graphs).
[[nodiscard]] inline bool is_graph_architecture(std::string_view architecture) noexcept {
  return architecture.find(kGraphArchitectureMark) != std::string_view::npos;
}

}  // namespace esc::control
