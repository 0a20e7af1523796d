#pragma once
// Units of measure in scripts: every quantity is lowered to SI (m, s, rad, kg) here, for
// scripts and for `esc run --set` values alike.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace esc::compiler {

enum class Dim { None, Length, Time, Angle, Speed, Accel, Mass, Area, TurnRate, TurnAccel };

struct Unit {
  std::string_view name;   // as written: "cm", "m/s^2"
  Dim dim;
  double to_si;            // multiply a value in this unit to get SI
};

[[nodiscard]] std::optional<Unit> find_unit(std::string_view name) noexcept;
// Every unit name, for "did you mean" and the documentation.
[[nodiscard]] std::vector<std::string> unit_names();
// Whether `word` alone is a unit name that may stand apart from its number (`0.5 m/s^2`).
[[nodiscard]] bool is_unit_word(std::string_view word) noexcept;

// "a length", "a time", ..., "a plain number".
[[nodiscard]] std::string_view dim_phrase(Dim d) noexcept;
// The SI unit a dimension is lowered to ("m", "s", "rad", "m/s", "m/s^2", "kg", "").
[[nodiscard]] std::string_view si_unit(Dim d) noexcept;
// A unit to suggest in help lines ("cm" for lengths, ...).
[[nodiscard]] std::string_view example_unit(Dim d) noexcept;

}  // namespace esc::compiler
