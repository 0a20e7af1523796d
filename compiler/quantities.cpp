#include "compiler/quantities.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "compiler/names.hpp"

namespace esc::compiler {

Reading read_quantity(double value, std::string_view text, std::string_view unit, Dim want) {
  Reading r;
  if (unit.empty()) {
    if (want == Dim::None || value == 0.0) {
      r.ok = true;
      r.si = value;
      return r;
    }
    r.message = fmt::format("missing unit: expected {}", dim_phrase(want));
    r.help = fmt::format("write `{}{}`", text, example_unit(want));
    return r;
  }
  const auto u = find_unit(unit);
  if (!u) {
    r.message = fmt::format("unknown unit `{}`", unit);
    if (auto best = closest(unit, unit_names()))
      r.message += fmt::format("; did you mean `{}`?", *best);
    else
      r.help = "units are mm, cm, m, ms, s, deg, rad, mm/s, cm/s, m/s, mm/s^2, cm/s^2, m/s^2, g, kg";
    if (unit.find('/') != std::string_view::npos)
      r.help = fmt::format("to divide by a name, put the quantity in parentheses: `({}{}) / ...`", text,
                           unit.substr(0, unit.find('/')));
    return r;
  }
  if (u->dim != want) {
    if (want == Dim::None)
      r.message = fmt::format("expected a plain number, found {} (`{}`)", dim_phrase(u->dim), unit);
    else
      r.message = fmt::format("expected {}, found {} (`{}`)", dim_phrase(want), dim_phrase(u->dim), unit);
    if (want != Dim::None) r.help = fmt::format("write `{}{}`", text, example_unit(want));
    else r.help = fmt::format("write `{}`", text);
    return r;
  }
  r.ok = true;
  r.si = value * u->to_si;
  return r;
}

std::optional<double> to_si(const ast::Quantity& q, Dim want, Sink& sink) {
  if (!q.finite) return std::nullopt;
  const Reading r = read_quantity(q.value, q.text, q.unit, want);
  if (r.ok) return r.si;
  Diagnostic& d = sink.error(q.unit.empty() ? q.where : q.unit_where, r.message);
  if (!r.help.empty()) d.help.push_back(r.help);
  return std::nullopt;
}

Reading read_whole(double value, std::string_view text, std::string_view unit, std::string_view what,
                   long long min, long long max) {
  Reading r;
  if (!unit.empty()) {
    r.message = fmt::format("{} is a count and takes no unit, found `{}`", what, unit);
    r.help = fmt::format("write `{}`", text);
    return r;
  }
  if (value != std::floor(value)) {
    r.message = fmt::format("{} must be a whole number, found `{}`", what, text);
    return r;
  }
  if (value < static_cast<double>(min)) {
    r.message = fmt::format("{} must be at least {}, found {}", what, min, text);
    return r;
  }
  if (value > static_cast<double>(max)) {
    r.message = fmt::format("{} must be at most {}, found {}", what, max, text);
    return r;
  }
  r.ok = true;
  r.si = value;
  return r;
}

std::optional<long long> to_whole(const ast::Quantity& q, std::string_view what, long long min, long long max,
                                  Sink& sink) {
  if (!q.finite) return std::nullopt;
  const Reading r = read_whole(q.value, q.text, q.unit, what, min, max);
  if (r.ok) return static_cast<long long>(r.si);
  Diagnostic& d = sink.error(q.unit.empty() ? q.where : q.unit_where, r.message);
  if (!r.help.empty()) d.help.push_back(r.help);
  return std::nullopt;
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
