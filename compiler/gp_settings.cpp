#include "compiler/gp_settings.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"

namespace esc::compiler {

namespace {

using K = GpOption::Kind;
using S = evo::gp::GpSettings;

// A plain number written in `text` (spaces around it allowed), or nullopt.
std::optional<double> plain(std::string_view text) {
  double v = 0;
  std::string unit;
  if (!split_value(text, v, unit) || !unit.empty()) return std::nullopt;
  return v;
}

// A single tree controller's set (a Number terminal) for settings no tree is compared with.
const evo::gp::PrimitiveSet& neutral_set() {
  static const evo::gp::PrimitiveSet set({evo::gp::prim::constant(evo::gp::Type::Number, 0.0)},
                                         evo::gp::Type::Number);
  return set;
}

std::string without_prefix(std::string message) {
  constexpr std::string_view prefix = "genetic programming: ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

}  // namespace

const std::vector<GpOption>& gp_options() {
  static const std::vector<GpOption> table = {
      {"population", K::Whole, 1, &S::population, nullptr},
      {"generations", K::Whole, 1, &S::generations, nullptr},
      {"tournament", K::Whole, 1, &S::tournament, nullptr},
      {"elitism", K::Whole, 0, &S::elitism, nullptr},
      {"crossover", K::Fraction, 0, nullptr, &S::crossover},
      {"subtree_mutation", K::Fraction, 0, nullptr, &S::subtree_mutation},
      {"point_mutation", K::Fraction, 0, nullptr, &S::point_mutation},
      {"hoist_mutation", K::Fraction, 0, nullptr, &S::hoist_mutation},
      {"max_depth", K::Whole, 1, &S::max_depth, nullptr},
      {"max_size", K::Whole, 1, &S::max_size, nullptr},
      {"init_depth", K::Depths, 1, nullptr, nullptr},
      {"mutation_depth", K::Whole, 1, &S::mutation_depth, nullptr},
      {"internal_bias", K::Fraction, 0, nullptr, &S::internal_bias},
      {"erc_sigma", K::Plain, 0, nullptr, &S::erc_sigma},
  };
  return table;
}

const GpOption* find_gp_option(std::string_view name) {
  for (const GpOption& o : gp_options())
    if (o.name == name) return &o;
  return nullptr;
}

std::vector<std::string> gp_option_names() {
  std::vector<std::string> names;
  for (const GpOption& o : gp_options()) names.emplace_back(o.name);
  return names;
}

std::string set_gp_option(S& s, const GpOption& o, double value, double hi) {
  constexpr double kIntMax = std::numeric_limits<int>::max();
  const auto whole = [&](double v, double min) -> std::string {
    if (!(std::floor(v) == v && v >= min && v <= kIntMax))
      return fmt::format("`{}` takes a whole number of at least {}, found {}", o.name, min, number_text(v));
    return {};
  };
  switch (o.kind) {
    case K::Whole:
      if (std::string m = whole(value, static_cast<double>(o.min)); !m.empty()) return m;
      s.*o.whole = static_cast<int>(value);
      return {};
    case K::Fraction:
      if (!(value >= 0.0 && value <= 1.0))
        return fmt::format("`{}` is a probability in [0, 1], found {}", o.name, number_text(value));
      s.*o.real = value;
      return {};
    case K::Plain:
      if (!(std::isfinite(value) && value >= 0.0))
        return fmt::format("`{}` must be at least 0, found {}", o.name, number_text(value));
      s.*o.real = value;
      return {};
    case K::Depths:
      if (std::string m = whole(value, 1); !m.empty()) return m;
      if (std::string m = whole(hi, 1); !m.empty()) return m;
      if (hi < value)
        return fmt::format("`init_depth [{}, {}]` is empty: the first depth must not exceed the second",
                           number_text(value), number_text(hi));
      s.init_min_depth = static_cast<int>(value);
      s.init_max_depth = static_cast<int>(hi);
      return {};
  }
  return {};
}

std::string apply_gp_setting(eval::ExperimentSpec& spec, std::string_view key, std::string_view value) {
  const GpOption* o = find_gp_option(key);
  if (o == nullptr) {
    std::string err = fmt::format("unknown GP setting `gp.{}`", key);
    if (auto best = closest(key, gp_option_names())) err += fmt::format("; did you mean `gp.{}`?", *best);
    return err + fmt::format(" (GP settings: {})", fmt::join(gp_option_names(), ", "));
  }
  S scratch = spec.gp.value_or(S{});
  if (o->kind == K::Depths) {
    std::string v(value);
    if (!v.empty() && v.front() == '[') v.erase(0, 1);
    if (!v.empty() && v.back() == ']') v.pop_back();
    const std::size_t comma = v.find(',');
    const auto lo = comma == std::string::npos ? std::nullopt : plain(v.substr(0, comma));
    const auto hi = comma == std::string::npos ? std::nullopt : plain(v.substr(comma + 1));
    if (!lo || !hi) return fmt::format("`gp.init_depth` takes two whole numbers, as in `[2, 6]`, found `{}`", value);
    if (std::string m = set_gp_option(scratch, *o, *lo, *hi); !m.empty()) return m;
  } else {
    const auto v = plain(value);
    if (!v) return fmt::format("`gp.{}` takes a plain number, found `{}`", key, value);
    if (std::string m = set_gp_option(scratch, *o, *v); !m.empty()) return m;
  }
  if (spec.gp) spec.gp = scratch;
  return {};
}

std::string check_gp(const eval::ExperimentSpec& spec) {
  if (!spec.gp) return {};
  bool any_tree = false;
  for (const control::ControllerSpec& c : spec.controllers) {
    if (!c.is_tree()) continue;
    any_tree = true;
    try {
      (void)evo::gp::GeneticProgramming(*spec.gp, *c.primitives);
    } catch (const std::invalid_argument& e) {
      return fmt::format("impossible GP settings for tree controller `{}`: {}", c.name, without_prefix(e.what()));
    }
  }
  if (!any_tree) {
    try {
      (void)evo::gp::GeneticProgramming(*spec.gp, neutral_set());
    } catch (const std::invalid_argument& e) {
      return fmt::format("impossible GP settings: {}", without_prefix(e.what()));
    }
  }
  return {};
}

void resolve_gp_settings(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  for (auto it = r.begin(); it != r.end();) it = it->first.rfind("gp.", 0) == 0 ? r.erase(it) : std::next(it);
  if (!spec.gp) return;
  const S& s = *spec.gp;
  for (const GpOption& o : gp_options()) {
    const std::string key = "gp." + std::string(o.name);
    switch (o.kind) {
      case K::Whole: r[key] = std::to_string(s.*o.whole); break;
      case K::Fraction:
      case K::Plain: r[key] = number_text(s.*o.real); break;
      case K::Depths: r[key] = fmt::format("[{}, {}]", s.init_min_depth, s.init_max_depth); break;
    }
  }
}

}  // namespace esc::compiler
