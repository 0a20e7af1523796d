#pragma once
// Reading written values: quantities with units (lowered to SI) and whole numbers, with
// the same rules and messages for scripts and for `esc run --set` values.
#include <optional>
#include <string>
#include <string_view>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "compiler/units.hpp"

namespace esc::compiler {

struct Reading {
  bool ok = false;
  double si = 0.0;
  std::string message;   // when !ok
  std::string help;      // may be empty
};

// `value` written with `unit` ("" when none), read as dimension `want`. A bare 0 is accepted
// for any dimension; any other bare number needs a unit when `want` has one.
[[nodiscard]] Reading read_quantity(double value, std::string_view number_text, std::string_view unit, Dim want);

// The same, reporting to `sink` at the quantity's location.
[[nodiscard]] std::optional<double> to_si(const ast::Quantity& q, Dim want, Sink& sink);

// A whole number without a unit, at least `min`; `what` names it in messages ("`runs`").
[[nodiscard]] std::optional<long long> to_whole(const ast::Quantity& q, std::string_view what, long long min,
                                                long long max, Sink& sink);
[[nodiscard]] Reading read_whole(double value, std::string_view text, std::string_view unit,
                                 std::string_view what, long long min, long long max);

// Parses "50ms", "0.5 m/s^2", "-1", "1e-3" into number and unit; false when not a number.
[[nodiscard]] bool split_value(std::string_view text, double& value, std::string& unit);

// Shortest text that reads back as `v` ("0.08", "1e-06").
[[nodiscard]] std::string number_text(double v);

}  // namespace esc::compiler
