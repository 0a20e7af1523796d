#include "compiler/lower_success.hpp"

#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/units.hpp"

namespace esc::compiler {

namespace {

using Of = eval::SuccessSpec::Of;
using Test = eval::SuccessSpec::Test;

// What NAME can be: an objective or a descriptor, with the item that declares its range.
struct Candidate {
  std::string name;
  Of of;
  std::size_t index;
  const ast::ExpItem* item;   // null: the fitness, declared without an item of its range
};

std::vector<Candidate> candidates(const ObjectiveItems& items, const eval::ExperimentSpec& x) {
  std::vector<Candidate> all{{x.fitness.name, Of::Objective, 0, items.fitness}};
  // x.objectives[0] is the fitness; further objective i is x.objectives[i + 1], declared by
  // items.objectives[i] (all of them lowered, or this is not reached).
  for (std::size_t i = 1; i < x.objectives.size() && i - 1 < items.objectives.size(); ++i)
    all.push_back({x.objectives[i].name, Of::Objective, i, items.objectives[i - 1]});
  for (std::size_t i = 0; i < x.descriptors.size() && i < items.descriptors.size(); ++i)
    all.push_back({x.descriptors[i].name, Of::Descriptor, i, items.descriptors[i]});
  return all;
}

// The dimension of a declared range's unit (`in [-1.2m, 0]`: a length); none when its bounds
// are plain numbers or it is not declared. A bound's unknown unit was reported with the range.
std::optional<Dim> range_dimension(const ast::ExpItem* item) {
  if (item == nullptr || !item->range) return std::nullopt;
  for (const ast::Quantity* q : {&item->range->lo, &item->range->hi})
    if (!q->unit.empty())
      if (const auto u = find_unit(q->unit)) return u->dim;
  return std::nullopt;
}

std::optional<Test> test_of(std::string_view compare) {
  if (compare == "<") return Test::Below;
  if (compare == "<=") return Test::AtMost;
  if (compare == ">") return Test::Above;
  if (compare == ">=") return Test::AtLeast;
  return std::nullopt;   // a syntax error, reported by the parser
}

// The threshold in SI: in the dimension of the range when it has one (a bare number, 0
// excepted, then needs a unit), else any known unit scaled to SI, as a range's bounds are.
std::optional<double> threshold(const ast::Quantity& q, const Candidate& c, Sink& sink) {
  const std::optional<Dim> dim = range_dimension(c.item);
  if (!dim) return value_in_si(q, sink);
  const int errors = sink.errors();
  const auto v = to_si(q, *dim, sink);
  if (sink.errors() != errors)
    sink.items().back().notes.emplace_back(
        c.item->range->where, fmt::format("the range of `{}` is {}", c.name, dim_phrase(*dim)));
  return v;
}

}  // namespace

bool lower_success(const ast::ExpItem& item, const ObjectiveItems& objectives, Sink& sink, eval::ExperimentSpec& x) {
  const ast::Name& ref = item.refs.at(0);
  const auto test = test_of(item.compare);
  if (ref.text.empty() || item.numbers.empty() || !test) return false;   // a syntax error, reported
  std::vector<Candidate> matches, all = candidates(objectives, x);
  std::vector<std::string> names;
  for (const Candidate& c : all) {
    names.push_back(c.name);
    if (c.name == ref.text) matches.push_back(c);
  }
  // One match at most: lower_objectives refuses a descriptor named like an objective.
  if (matches.empty()) {
    Diagnostic& d = sink.error(
        ref.where, fmt::format("`{}` is neither an objective nor a descriptor of this experiment", ref.text));
    suggest(d, ref.text, names,
            {.otherwise = fmt::format("a success test reads the fitness, a further objective or a descriptor: {}",
                                      quoted_list(names)),
             .always = true});
    return false;
  }
  const auto value = threshold(item.numbers[0], matches[0], sink);
  if (!value) return false;
  x.success = eval::SuccessSpec{ref.text, matches[0].of, matches[0].index, *test, *value};
  return true;
}

void resolve_success(eval::ExperimentSpec& x) {
  if (x.success) x.resolved_settings["success"] = x.success->text();
}

}  // namespace esc::compiler
