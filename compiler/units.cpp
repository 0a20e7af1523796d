#include "compiler/units.hpp"

#include <array>
#include <numbers>

namespace esc::compiler {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

constexpr std::array kUnits = {
    Unit{"mm", Dim::Length, 1e-3},      Unit{"cm", Dim::Length, 1e-2},
    Unit{"m", Dim::Length, 1.0},        Unit{"ms", Dim::Time, 1e-3},
    Unit{"s", Dim::Time, 1.0},          Unit{"deg", Dim::Angle, kDeg},
    Unit{"rad", Dim::Angle, 1.0},       Unit{"mm/s", Dim::Speed, 1e-3},
    Unit{"cm/s", Dim::Speed, 1e-2},     Unit{"m/s", Dim::Speed, 1.0},
    Unit{"mm/s^2", Dim::Accel, 1e-3},   Unit{"cm/s^2", Dim::Accel, 1e-2},
    Unit{"m/s^2", Dim::Accel, 1.0},     Unit{"g", Dim::Mass, 1e-3},
    Unit{"kg", Dim::Mass, 1.0},
    // Areas: a number's unit is one word (`0.7cm2`), so that `2cm^2` in an expression stays (2 cm)^2.
    Unit{"mm2", Dim::Area, 1e-6},       Unit{"cm2", Dim::Area, 1e-4},
    Unit{"m2", Dim::Area, 1.0},
    Unit{"deg/s", Dim::TurnRate, kDeg},   Unit{"rad/s", Dim::TurnRate, 1.0},
    Unit{"deg/s^2", Dim::TurnAccel, kDeg}, Unit{"rad/s^2", Dim::TurnAccel, 1.0},
};

}  // namespace

std::optional<Unit> find_unit(std::string_view name) noexcept {
  for (const Unit& u : kUnits)
    if (u.name == name) return u;
  return std::nullopt;
}

std::vector<std::string> unit_names() {
  std::vector<std::string> names;
  for (const Unit& u : kUnits) names.emplace_back(u.name);
  return names;
}

bool is_unit_word(std::string_view word) noexcept {
  for (const Unit& u : kUnits)
    if (u.name == word) return true;
  return false;
}

std::string_view dim_phrase(Dim d) noexcept {
  switch (d) {
    case Dim::Length: return "a length";
    case Dim::Time: return "a time";
    case Dim::Angle: return "an angle";
    case Dim::Speed: return "a speed";
    case Dim::Accel: return "an acceleration";
    case Dim::Mass: return "a mass";
    case Dim::Area: return "an area";
    case Dim::TurnRate: return "a turn rate";
    case Dim::TurnAccel: return "a turn acceleration";
    case Dim::None: break;
  }
  return "a plain number";
}

std::string_view si_unit(Dim d) noexcept {
  switch (d) {
    case Dim::Length: return "m";
    case Dim::Time: return "s";
    case Dim::Angle: return "rad";
    case Dim::Speed: return "m/s";
    case Dim::Accel: return "m/s^2";
    case Dim::Mass: return "kg";
    case Dim::Area: return "m2";
    case Dim::TurnRate: return "rad/s";
    case Dim::TurnAccel: return "rad/s^2";
    case Dim::None: break;
  }
  return "";
}

std::string_view example_unit(Dim d) noexcept {
  switch (d) {
    case Dim::Length: return "cm";
    case Dim::Time: return "ms";
    case Dim::Angle: return "deg";
    case Dim::Speed: return "cm/s";
    case Dim::Accel: return "m/s^2";
    case Dim::Mass: return "g";
    case Dim::Area: return "cm2";
    case Dim::TurnRate: return "deg/s";
    case Dim::TurnAccel: return "deg/s^2";
    case Dim::None: break;
  }
  return "";
}

}  // namespace esc::compiler
