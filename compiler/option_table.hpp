#pragma once
// The table shape of a settings group whose options scripts write in `evolve es(...)` and
// `evolve gp(...)`: one row per option (its key in scripts, `--set` and resolved settings,
// how it is written, how its value is read and checked, its text), the lookups, and the
// reading of a script's option list, shared by the ES and the GP.
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "compiler/ast.hpp"
#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/sink.hpp"
#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/limits.hpp"

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
  // are the experiment's, for the ES and the GP alike.
  bool own_key = true;
  // The algorithm's own row, where the table is read from its folder (algorithm_options.hpp).
  const evo::AlgorithmOption* option = nullptr;
};

// A whole number of at least Min into an int field; its text. A field, here and below, is
// a member pointer of Settings or of a base it extends (GP's settings extend the tree
// kind's operators, runtime/genome/tree/tree_operators.hpp).
template <class Settings, auto Field, long long Min>
bool read_whole(const OptionRow<Settings>& o, Settings& s, const ast::Value& v, Sink& sink) {
  const auto n = read_count(v, o.key, Min, std::numeric_limits<int>::max(), sink);
  if (n) s.*Field = static_cast<int>(*n);
  return n.has_value();
}
template <class Settings, auto Field>
std::string whole_text(const OptionRow<Settings>&, const Settings& s) {
  return std::to_string(s.*Field);
}

// What a plain number must be.
enum class RealRange { Probability, Positive, NonNegative };

// A plain number in its range, and at most *Max when given (the algorithm's limit that keeps
// its arithmetic finite), into a double field; its text. A pointer, since clang 14 (the fuzz
// build) takes no double template argument.
template <class Settings, auto Field, RealRange R, const double* Max = nullptr>
bool read_real(const OptionRow<Settings>& o, Settings& s, const ast::Value& v, Sink& sink) {
  const auto x = read_quantity(v, o.key, Dim::None, sink);
  if (!x) return false;
  const bool ok = R == RealRange::Probability ? *x >= 0.0 && *x <= 1.0
                  : R == RealRange::Positive  ? *x > 0.0
                                              : *x >= 0.0;
  if (!ok) {
    sink.error(v.where, fmt::format("`{}` {}, found {}", o.key,
                                    R == RealRange::Probability ? "is a probability in [0, 1]"
                                    : R == RealRange::Positive  ? "must be greater than 0"
                                                                : "must be at least 0",
                                    number_text(*x)));
    return false;
  }
  if constexpr (Max != nullptr) {
    if (*x > *Max) {
      sink.error(v.where, fmt::format("`{}` must be at most {}, found {}", o.key, number_text(*Max), number_text(*x)));
      return false;
    }
  }
  s.*Field = *x;
  return true;
}
template <class Settings, auto Field>
std::string real_text(const OptionRow<Settings>&, const Settings& s) {
  return number_text(s.*Field);
}

// `bounds [LO, HI]` of the genes (a network's weights), within +-evo::kMaxGeneBound, into
// the `lower` and `upper` fields; its text.
template <class Settings>
bool read_gene_bounds(const OptionRow<Settings>& o, Settings& s, const ast::Value& v, Sink& sink) {
  const auto r = read_range(v, o.key, "[-1, 1]", sink);
  if (!r) return false;
  if (std::abs(r->first) > evo::kMaxGeneBound || std::abs(r->second) > evo::kMaxGeneBound) {
    sink.error(v.where, fmt::format("bounds must lie within [-{0}, {0}], found [{1}, {2}]", number_text(evo::kMaxGeneBound),
                                    number_text(r->first), number_text(r->second)))
        .help.push_back("beyond that the steps and the networks' sums lose their precision and can overflow; "
                        "scale the inputs instead");
    return false;
  }
  if (!(r->first < r->second)) {
    sink.error(v.where, fmt::format("empty bounds: the lower bound ({}) must be below the upper ({})",
                                    number_text(r->first), number_text(r->second)));
    return false;
  }
  s.lower = r->first;
  s.upper = r->second;
  return true;
}
template <class Settings>
std::string gene_bounds_text(const OptionRow<Settings>&, const Settings& s) {
  return fmt::format("[{}, {}]", number_text(s.lower), number_text(s.upper));
}

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
// and each value its row refuses. `what` names the group in messages ("ES"); `defaults`
// gives the example shown for a value written with the wrong shape.
template <class Settings>
void read_options(const ast::ExpItem& item, std::string_view method, std::string_view what,
                  const std::vector<OptionRow<Settings>>& table, Settings& s, Sink& sink,
                  const Settings& defaults = Settings{}) {
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
  if (!item.generations) return;
  const OptionRow<Settings>* generations = find_option_word(table, "generations");
  if (seen.count(generations) != 0)
    sink.error(item.generations->where, fmt::format("the number of generations is already given in `{}(...)`", method));
  else if (item.generations->finite)
    (void)generations->read(*generations, s, as_value(*item.generations), sink);
}

}  // namespace esc::compiler
