#include "compiler/quantities.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "compiler/names.hpp"

namespace esc::compiler {

std::optional<double> to_si(const ast::Quantity& q, Dim want, Sink& sink) {
  if (!q.finite) return std::nullopt;
  if (q.unit.empty()) {
    if (want == Dim::None || q.value == 0.0) return q.value;
    sink.error(q.where, fmt::format("missing unit: expected {}", dim_phrase(want)))
        .help.push_back(fmt::format("write `{}{}`", q.text, example_unit(want)));
    return std::nullopt;
  }
  const auto u = find_unit(q.unit);
  if (!u) {
    Diagnostic& d = sink.error(q.unit_where, fmt::format("unknown unit `{}`", q.unit));
    suggest(d, q.unit, unit_names(),
            {.otherwise = "units are mm, cm, m, ms, s, deg, rad, mm/s, cm/s, m/s, mm/s^2, cm/s^2, m/s^2, g, kg"});
    if (const std::size_t slash = q.unit.find('/'); slash != std::string::npos)
      d.help = {fmt::format("to divide by a name, put the quantity in parentheses: `({}{}) / ...`", q.text,
                            q.unit.substr(0, slash))};
    return std::nullopt;
  }
  if (u->dim != want) {
    Diagnostic& d = sink.error(
        q.unit_where, want == Dim::None
                          ? fmt::format("expected a plain number, found {} (`{}`)", dim_phrase(u->dim), q.unit)
                          : fmt::format("expected {}, found {} (`{}`)", dim_phrase(want), dim_phrase(u->dim), q.unit));
    d.help.push_back(fmt::format("write `{}{}`", q.text, want == Dim::None ? "" : example_unit(want)));
    return std::nullopt;
  }
  return q.value * u->to_si;
}

std::optional<long long> to_whole(const ast::Quantity& q, std::string_view what, long long min, long long max,
                                  Sink& sink) {
  if (!q.finite) return std::nullopt;
  std::string message;
  if (!q.unit.empty()) {
    sink.error(q.unit_where, fmt::format("{} is a count and takes no unit, found `{}`", what, q.unit))
        .help.push_back(fmt::format("write `{}`", q.text));
    return std::nullopt;
  }
  if (q.value != std::floor(q.value))
    message = fmt::format("{} must be a whole number, found `{}`", what, q.text);
  else if (q.value < static_cast<double>(min))
    message = fmt::format("{} must be at least {}, found {}", what, min, q.text);
  else if (q.value > static_cast<double>(max))
    message = fmt::format("{} must be at most {}, found {}", what, max, q.text);
  if (!message.empty()) {
    sink.error(q.where, message);
    return std::nullopt;
  }
  return static_cast<long long>(q.value);
}

bool split_value(std::string_view text, double& value, std::string& unit) {
  std::size_t i = 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  std::size_t start = i;
  if (i < text.size() && text[i] == '+') start = ++i;
  const auto res = std::from_chars(text.data() + start, text.data() + text.size(), value);
  if (res.ec != std::errc() || !std::isfinite(value)) return false;
  unit.clear();
  for (const char* p = res.ptr; p < text.data() + text.size(); ++p)
    if (*p != ' ' && *p != '\t') unit += *p;
  return true;
}

std::string number_text(double v) { return fmt::format("{}", v); }

}  // namespace esc::compiler
