#include "compiler/es_options.hpp"

#include <limits>
#include <map>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"

namespace esc::compiler {

namespace {

using S = evo::EsSettings;
using Shape = OptionShape;
constexpr long long kIntMax = std::numeric_limits<int>::max();

// The counts: at least 1.
bool read_count_into(int S::*field, const EsOption& o, S& s, const ast::Value& v, Sink& sink) {
  const auto n = read_count(v, o.key, 1, kIntMax, sink);
  if (n) s.*field = static_cast<int>(*n);
  return n.has_value();
}

// The step sizes: plain numbers above 0, or at least 0 when `zero_ok`.
bool read_step(double S::*field, bool zero_ok, const EsOption& o, S& s, const ast::Value& v, Sink& sink) {
  const auto x = read_quantity(v, o.key, Dim::None, sink);
  if (!x) return false;
  if (zero_ok ? !(*x >= 0) : !(*x > 0)) {
    sink.error(v.where, fmt::format("`{}` must be {} 0, found {}", o.key, zero_ok ? "at least" : "greater than",
                                    number_text(*x)));
    return false;
  }
  s.*field = *x;
  return true;
}

// A choice: the index of the word `v` among `o.words`.
template <class E>
bool read_choice(E S::*field, const EsOption& o, S& s, const ast::Value& v, Sink& sink) {
  const auto i = read_word(v, o.key, o.words, sink);
  if (i) s.*field = static_cast<E>(*i);
  return i.has_value();
}

}  // namespace

const std::vector<EsOption>& es_options() {
  // A choice's words are in the order of its enum's values.
  static const std::vector<EsOption> table = {
      {"mu", Shape::Value, "parents",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_count_into(&S::mu, o, s, v, k); },
       [](const EsOption&, const S& s) { return std::to_string(s.mu); }},
      {"lambda", Shape::Value, "offspring per generation",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_count_into(&S::lambda, o, s, v, k); },
       [](const EsOption&, const S& s) { return std::to_string(s.lambda); }},
      {"selection", Shape::Word, "parents from the offspring only (`comma`) or from both (`plus`)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_choice(&S::selection, o, s, v, k); },
       [](const EsOption& o, const S& s) { return o.words[static_cast<std::size_t>(s.selection)]; },
       {"comma", "plus"}},
      {"recombination", Shape::Word, "of the two parents of each offspring",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_choice(&S::recombination, o, s, v, k); },
       [](const EsOption& o, const S& s) { return o.words[static_cast<std::size_t>(s.recombination)]; },
       {"intermediate", "discrete", "no_recombination"}},
      {"step_sizes", Shape::Word, "one sigma for all genes (`one_sigma`) or one per gene (`self_adaptive`)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_choice(&S::step_sizes, o, s, v, k); },
       [](const EsOption& o, const S& s) { return o.words[static_cast<std::size_t>(s.step_sizes)]; },
       {"one_sigma", "self_adaptive"}},
      {"bounds", Shape::Range, "genes stay in [LO, HI] (LO < HI)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) {
         const auto r = read_range(v, o.key, "[-1, 1]", k);
         if (!r) return false;
         if (!(r->first < r->second)) {
           k.error(v.where, fmt::format("empty bounds: the lower bound ({}) must be below the upper ({})",
                                        number_text(r->first), number_text(r->second)));
           return false;
         }
         s.lower = r->first;
         s.upper = r->second;
         return true;
       },
       [](const EsOption&, const S& s) { return fmt::format("[{}, {}]", number_text(s.lower), number_text(s.upper)); }},
      {"sigma", Shape::Value, "initial step size, a fraction of HI - LO (> 0)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_step(&S::initial_sigma, false, o, s, v, k); },
       [](const EsOption&, const S& s) { return number_text(s.initial_sigma); }},
      {"min_sigma", Shape::Value, "floor of the step sizes (>= 0)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_step(&S::min_sigma, true, o, s, v, k); },
       [](const EsOption&, const S& s) { return number_text(s.min_sigma); }},
      {"generations", Shape::Value, "generations (also `for N generations`)",
       [](const EsOption& o, S& s, const ast::Value& v, Sink& k) { return read_count_into(&S::generations, o, s, v, k); },
       [](const EsOption&, const S& s) { return std::to_string(s.generations); },
       {},
       false},
  };
  return table;
}

const EsOption* find_es_option_word(std::string_view word) {
  for (const EsOption& o : es_options()) {
    if (o.shape != Shape::Word && o.key == word) return &o;
    for (const std::string& w : o.words)
      if (w == word) return &o;
  }
  return nullptr;
}

const EsOption* find_es_option_key(std::string_view key) {
  for (const EsOption& o : es_options())
    if (o.own_key && o.key == key) return &o;
  return nullptr;
}

std::vector<std::string> es_option_words() {
  std::vector<std::string> v;
  for (const EsOption& o : es_options()) {
    if (o.shape != Shape::Word) v.emplace_back(o.key);
    v.insert(v.end(), o.words.begin(), o.words.end());
  }
  return v;
}

std::optional<EsProblem> es_problem(const S& s) {
  if (s.selection == evo::Selection::Comma && s.lambda < s.mu)
    return EsProblem{fmt::format("comma selection needs `lambda` >= `mu`, found mu {} and lambda {}", s.mu, s.lambda),
                     "raise `lambda`, or use `plus` selection"};
  return std::nullopt;
}

void lower_es_item(const ast::ExpItem& item, S& es, Sink& sink) {
  std::map<const EsOption*, const ast::EsOption*> seen;
  const S defaults;
  const int errors = sink.errors();
  for (const ast::EsOption& o : item.options) {
    const std::string& n = o.name.text;
    if (n.empty()) continue;
    const EsOption* opt = find_es_option_word(n);
    if (opt == nullptr) {
      suggest(sink.error(o.name.where, fmt::format("unknown ES option `{}`", n)), n, es_option_words(),
              {.otherwise = fmt::format("ES options: {}", fmt::join(es_option_words(), ", "))});
      continue;
    }
    if (auto [it, fresh] = seen.try_emplace(opt, &o); !fresh) {
      const std::string what = opt->shape == Shape::Word ? fmt::format("the {}", opt->key) : fmt::format("`{}`", n);
      sink.error(o.where, fmt::format("{} is already given", what)).notes.emplace_back(it->second->where, "first given here");
      continue;
    }
    if (const auto v = option_value(o, opt->shape, opt->text(*opt, defaults), sink)) (void)opt->read(*opt, es, *v, sink);
  }
  if (item.generations) {
    if (seen.count(find_es_option_word("generations")) != 0)
      sink.error(item.generations->where, "the number of generations is already given in `es(...)`");
    else if (auto v = to_whole(*item.generations, "`generations`", 1, kIntMax, sink))
      es.generations = static_cast<int>(*v);
  }
  if (sink.errors() != errors) return;
  if (const auto p = es_problem(es)) sink.error(item.where, p->message).help.push_back(p->help);
}

}  // namespace esc::compiler
