#pragma once
// Reading written numbers: quantities with units (lowered to SI) and whole numbers, with
// one message per mistake, located at the number or its unit; and the numbers' text.
#include <optional>
#include <string>
#include <string_view>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "compiler/units.hpp"

namespace esc::compiler {

// `q` read as dimension `want`, in SI. A bare 0 is accepted for any dimension; any other
// bare number needs a unit when `want` has one.
[[nodiscard]] std::optional<double> to_si(const ast::Quantity& q, Dim want, Sink& sink);

// A whole number without a unit in [min, max]; `what` names it in messages ("`runs`").
[[nodiscard]] std::optional<long long> to_whole(const ast::Quantity& q, std::string_view what, long long min,
                                                long long max, Sink& sink);

// Parses "50ms", "0.5 m/s^2", "-1", "1e-3" into number and unit; false when not a number.
[[nodiscard]] bool split_value(std::string_view text, double& value, std::string& unit);

// Shortest text that reads back as `v` ("0.08", "1e-06").
[[nodiscard]] std::string number_text(double v);

}  // namespace esc::compiler
