#pragma once
// The table shape of the options scripts write in `evolve NAME(...)`: one row per option
// (its key in scripts, `--set` and resolved settings, how it is written, how its value is
// read and checked, its text), the lookups, and the reading of a script's option list
// (algorithm_options.hpp makes the rows from each algorithm's own table).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "compiler/ast.hpp"
#include "compiler/names.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/sink.hpp"
#include "runtime/evo/algorithm_options.hpp"

namespace esc::compiler {

template <class Settings>
struct OptionRow {
  // In the option list (a choice: the group, whose words are written alone), `--set KEY`
  // (with the group's prefix) and resolved settings, unless `own_key` is false.
  std::string_view key;
  OptionShape shape;
  std::string_view summary;
  // Reads `v`, checks it alone and stores it; reports at `v`.
  bool (*read)(const OptionRow& o, Settings& s, const ast::Value& v, Sink& sink);
  std::string (*text)(const OptionRow& o, const Settings& s);
  std::vector<std::string> words = {};   // a choice's values, in the order of its enum
  // False for the ES's `generations`: `--set generations` and the resolved `generations`
  // are the experiment's.
  bool own_key = true;
  // The algorithm's own row (runtime/evo/algorithm_options.hpp).
  const evo::AlgorithmOption* option = nullptr;
  std::string example = {};   // a range's, in messages: its default (`[-1, 1]`)
};

// The row an option written `word` sets: its key, or one of a choice's words.
template <class Settings>
const OptionRow<Settings>* find_option_word(const std::vector<OptionRow<Settings>>& table, std::string_view word) {
  for (const OptionRow<Settings>& o : table) {
    if (o.shape != OptionShape::Word && o.key == word) return &o;
    for (const std::string& w : o.words)
      if (w == word) return &o;
  }
  return nullptr;
}

// The row of `--set` key `key` (without the group's prefix).
template <class Settings>
const OptionRow<Settings>* find_option_key(const std::vector<OptionRow<Settings>>& table, std::string_view key) {
  for (const OptionRow<Settings>& o : table)
    if (o.own_key && o.key == key) return &o;
  return nullptr;
}

// Every word an option list accepts, for "did you mean" and the documentation.
template <class Settings>
std::vector<std::string> option_words(const std::vector<OptionRow<Settings>>& table) {
  std::vector<std::string> v;
  for (const OptionRow<Settings>& o : table) {
    if (o.shape != OptionShape::Word) v.emplace_back(o.key);
    v.insert(v.end(), o.words.begin(), o.words.end());
  }
  return v;
}

// Every `--set` key of the group, with its prefix (`gp.`).
template <class Settings>
std::vector<std::string> option_keys(const std::vector<OptionRow<Settings>>& table, std::string_view prefix = {}) {
  std::vector<std::string> v;
  for (const OptionRow<Settings>& o : table)
    if (o.own_key) v.push_back(std::string(prefix) + std::string(o.key));
  return v;
}

// `evolve METHOD(OPTIONS) [for N generations]` into `s`: reports an unknown option (with
// "did you mean"), one whose setting is already given, one written with the wrong shape,
// and each value its row refuses. `for N generations` is read by the `generations` row where
// the table has one (else by the caller). `what` names the group in messages ("ES");
// `defaults` gives the example shown for a value written with the wrong shape.
template <class Settings>
void read_options(const ast::ExpItem& item, std::string_view method, std::string_view what,
                  const std::vector<OptionRow<Settings>>& table, Settings& s, Sink& sink,
                  const Settings& defaults) {
  std::map<const OptionRow<Settings>*, const ast::EsOption*> seen;
  for (const ast::EsOption& o : item.options) {
    const std::string& n = o.name.text;
    if (n.empty()) continue;
    const OptionRow<Settings>* row = find_option_word(table, n);
    if (row == nullptr) {
      suggest(sink.error(o.name.where, fmt::format("unknown {} option `{}`", what, n)), n, option_words(table),
              {.otherwise = fmt::format("{} options: {}", what, fmt::join(option_words(table), ", "))});
      continue;
    }
    if (auto [it, fresh] = seen.try_emplace(row, &o); !fresh) {
      const std::string given = row->words.empty() ? fmt::format("`{}`", n) : fmt::format("the {}", row->key);
      sink.error(o.where, fmt::format("{} is already given", given))
          .notes.emplace_back(it->second->where, "first given here");
      continue;
    }
    if (const auto v = option_value(o, row->shape, row->text(*row, defaults), sink)) (void)row->read(*row, s, *v, sink);
  }
  const OptionRow<Settings>* generations = find_option_word(table, "generations");
  if (!item.generations || generations == nullptr) return;
  if (seen.count(generations) != 0)
    sink.error(item.generations->where, fmt::format("the number of generations is already given in `{}(...)`", method));
  else if (item.generations->finite)
    (void)generations->read(*generations, s, as_value(*item.generations), sink);
}

}  // namespace esc::compiler
