#include "compiler/es_options.hpp"

#include <cmath>

#include <fmt/format.h>

#include "compiler/quantities.hpp"

namespace esc::compiler {

namespace {

using S = evo::EsSettings;
using Shape = OptionShape;

// A choice: the word `v` among `o.words`, the enum value of the same index.
template <class E, E S::*Field>
bool read_choice(const EsOption& o, S& s, const ast::Value& v, Sink& sink) {
  const auto i = read_word(v, o.key, o.words, sink);
  if (i) s.*Field = static_cast<E>(*i);
  return i.has_value();
}
template <class E, E S::*Field>
std::string choice(const EsOption& o, const S& s) {
  return o.words[static_cast<std::size_t>(s.*Field)];
}

}  // namespace

const std::vector<EsOption>& es_options() {
  using evo::Recombination, evo::Selection, evo::StepSizes;
  static const std::vector<EsOption> table = {
      {"mu", Shape::Value, "parents", &read_whole<S, &S::mu, 1>, &whole_text<S, &S::mu>},
      {"lambda", Shape::Value, "offspring per generation", &read_whole<S, &S::lambda, 1>, &whole_text<S, &S::lambda>},
      {"selection",
       Shape::Word,
       "the parents from the offspring only, or from parents and offspring",
       &read_choice<Selection, &S::selection>,
       &choice<Selection, &S::selection>,
       {"comma", "plus"}},
      {"recombination",
       Shape::Word,
       "of the two parents of each offspring",
       &read_choice<Recombination, &S::recombination>,
       &choice<Recombination, &S::recombination>,
       {"intermediate", "discrete", "no_recombination"}},
      {"step_sizes",
       Shape::Word,
       "one step size per individual, or one per gene",
       &read_choice<StepSizes, &S::step_sizes>,
       &choice<StepSizes, &S::step_sizes>,
       {"one_sigma", "self_adaptive"}},
      {"bounds", Shape::Range, "genes stay in [LO, HI] (LO < HI, both within +-1e6)", &read_gene_bounds<S>, &gene_bounds_text<S>},
      {"sigma", Shape::Value, "initial step size, a fraction of HI - LO (> 0, at most 1000)",
       &read_real<S, &S::initial_sigma, RealRange::Positive, &evo::kMaxStepSize>, &real_text<S, &S::initial_sigma>},
      {"min_sigma", Shape::Value, "floor of the step sizes (>= 0, at most HI - LO)",
       &read_real<S, &S::min_sigma, RealRange::NonNegative>, &real_text<S, &S::min_sigma>},
      {"generations",
       Shape::Value,
       "generations; also `for N generations`",
       &read_whole<S, &S::generations, 1>,
       &whole_text<S, &S::generations>,
       {},
       false},
  };
  return table;
}

std::optional<EsProblem> es_problem(const S& s) {
  if (s.selection == evo::Selection::Comma && s.lambda < s.mu)
    return EsProblem{fmt::format("comma selection needs `lambda` >= `mu`, found mu {} and lambda {}", s.mu, s.lambda),
                     "raise `lambda`, or use `plus` selection"};
  if (s.min_sigma > s.upper - s.lower)
    return EsProblem{fmt::format("`min_sigma` ({}) is wider than the bounds (HI - LO = {})", number_text(s.min_sigma),
                                 number_text(s.upper - s.lower)),
                     "every step would cross the whole interval: lower `min_sigma`"};
  return std::nullopt;
}

void lower_es_item(const ast::ExpItem& item, S& es, Sink& sink) {
  const int errors = sink.errors();
  read_options(item, "es", "ES", es_options(), es, sink);
  if (sink.errors() != errors) return;
  if (const auto p = es_problem(es)) sink.error(item.where, p->message).help.push_back(p->help);
}

}  // namespace esc::compiler
