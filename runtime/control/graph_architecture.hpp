#pragma once
// What marks a NEAT network's architecture string ("8-neat-2", ControllerSpec::architecture):
// how stored results, which keep the string and not the spec, tell a graph genome from a
// network's weights (the topology export, the report's network figures).
namespace esc::control {

inline constexpr const char* kGraphArchitectureMark = "-neat-";

}  // namespace esc::control
