#include "compiler/gp_settings.hpp"

#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using K = GpOption::Kind;
using S = evo::gp::GpSettings;
constexpr long long kIntMax = std::numeric_limits<int>::max();

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

// The text of an option's value in `s`: resolved settings, and the example of help lines.
std::string option_text(const GpOption& o, const S& s) {
  switch (o.kind) {
    case K::Whole: return std::to_string(s.*o.whole);
    case K::Fraction:
    case K::Plain: return number_text(s.*o.real);
    case K::Depths: return fmt::format("[{}, {}]", s.init_min_depth, s.init_max_depth);
  }
  return {};
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

bool read_gp_option(S& s, const GpOption& o, const ast::Value& v, Sink& sink) {
  switch (o.kind) {
    case K::Whole: {
      const auto n = read_count(v, o.name, o.min, kIntMax, sink);
      if (n) s.*o.whole = static_cast<int>(*n);
      return n.has_value();
    }
    case K::Fraction:
    case K::Plain: {
      const auto x = read_quantity(v, o.name, Dim::None, sink);
      if (!x) return false;
      if (o.kind == K::Fraction && !(*x >= 0.0 && *x <= 1.0)) {
        sink.error(v.where, fmt::format("`{}` is a probability in [0, 1], found {}", o.name, number_text(*x)));
        return false;
      }
      if (o.kind == K::Plain && !(*x >= 0.0)) {
        sink.error(v.where, fmt::format("`{}` must be at least 0, found {}", o.name, number_text(*x)));
        return false;
      }
      s.*o.real = *x;
      return true;
    }
    case K::Depths: {
      const auto r = read_range(v, o.name, "[2, 6]", sink);
      if (!r) return false;
      ast::Value lo = v, hi = v;
      lo.kind = hi.kind = ast::Value::Kind::Quantity;
      hi.q = v.hi;
      const auto first = read_count(lo, o.name, 1, kIntMax, sink), last = read_count(hi, o.name, 1, kIntMax, sink);
      if (!first || !last) return false;
      if (*last < *first) {
        sink.error(v.where, fmt::format("`init_depth [{}, {}]` is empty: the first depth must not exceed the second",
                                        *first, *last));
        return false;
      }
      s.init_min_depth = static_cast<int>(*first);
      s.init_max_depth = static_cast<int>(*last);
      return true;
    }
  }
  return false;
}

void lower_gp_item(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink) {
  S s = x.gp.value_or(S{});
  const S defaults;
  std::map<std::string, const ast::EsOption*> seen;
  for (const ast::EsOption& o : item.options) {
    const std::string& n = o.name.text;
    if (n.empty()) continue;
    const GpOption* opt = find_gp_option(n);
    if (opt == nullptr) {
      suggest(sink.error(o.name.where, fmt::format("unknown GP option `{}`", n)), n, gp_option_names(),
              {.otherwise = fmt::format("GP options: {}", fmt::join(gp_option_names(), ", "))});
      continue;
    }
    if (auto [it, fresh] = seen.try_emplace(n, &o); !fresh) {
      sink.error(o.where, fmt::format("`{}` is already given", n)).notes.emplace_back(it->second->where, "first given here");
      continue;
    }
    const OptionShape shape = opt->kind == K::Depths ? OptionShape::Range : OptionShape::Value;
    if (const auto v = option_value(o, shape, option_text(*opt, defaults), sink)) (void)read_gp_option(s, *opt, *v, sink);
  }
  if (item.generations) {
    if (seen.count("generations") != 0)
      sink.error(item.generations->where, "the number of generations is already given in `gp(...)`");
    else if (auto v = to_whole(*item.generations, "`generations`", 1, kIntMax, sink))
      s.generations = static_cast<int>(*v);
  }
  x.gp = s;
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
  for (const GpOption& o : gp_options()) r["gp." + std::string(o.name)] = option_text(o, *spec.gp);
}

}  // namespace esc::compiler
