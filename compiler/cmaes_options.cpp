#include "compiler/cmaes_options.hpp"

#include <stdexcept>
#include <string_view>

namespace esc::compiler {

namespace {

using S = evo::CmaesSettings;
using Shape = OptionShape;

bool read_covariance(const CmaesOption& o, S& s, const ast::Value& v, Sink& sink) {
  const auto i = read_word(v, o.key, o.words, sink);
  if (i) s.separable = *i == 1;
  return i.has_value();
}
std::string covariance(const CmaesOption& o, const S& s) { return o.words[s.separable ? 1 : 0]; }

}  // namespace

const std::vector<CmaesOption>& cmaes_options() {
  static const std::vector<CmaesOption> table = {
      {"lambda", Shape::Value, "candidates per generation; 0: 4 + floor(3 ln n)", &read_whole<S, &S::lambda, 0>,
       &whole_text<S, &S::lambda>},
      {"mu", Shape::Value, "parents recombined, at most lambda / 2; 0: lambda / 2", &read_whole<S, &S::mu, 0>,
       &whole_text<S, &S::mu>},
      {"sigma", Shape::Value, "initial step size, a fraction of HI - LO (> 0, at most 1000)",
       &read_real<S, &S::sigma, RealRange::Positive, &evo::kMaxStepSize>, &real_text<S, &S::sigma>},
      {"bounds", Shape::Range, "every weight stays in [LO, HI] (LO < HI, both within +-1e6)", &read_gene_bounds<S>,
       &gene_bounds_text<S>},
      {"covariance",
       Shape::Word,
       "a full covariance matrix, or its diagonal only (sep-CMA-ES, for networks of hundreds of weights)",
       &read_covariance,
       &covariance,
       {"full", "separable"}},
      {"restarts", Shape::Value, "IPOP: restarts with the population doubled after a stop; 0: none",
       &read_whole<S, &S::restarts, 0>, &whole_text<S, &S::restarts>},
      {"stop_sigma", Shape::Value, "stop when every coordinate's sd is below this fraction of HI - LO; 0: never",
       &read_real<S, &S::stop_sigma, RealRange::NonNegative>, &real_text<S, &S::stop_sigma>},
      {"stop_condition", Shape::Value, "stop when the covariance's condition number exceeds this",
       &read_real<S, &S::stop_condition, RealRange::Positive>, &real_text<S, &S::stop_condition>},
      {"stop_flat", Shape::Value, "stop after this many generations of equal best and worst fitness; 0: never",
       &read_whole<S, &S::stop_flat, 0>, &whole_text<S, &S::stop_flat>},
  };
  return table;
}

std::string cmaes_problem(const S& s, std::size_t genome_size) {
  try {
    (void)evo::Cmaes(s, genome_size);
  } catch (const std::invalid_argument& e) {
    std::string m = e.what();
    constexpr std::string_view prefix = "CMA-ES: ";
    if (m.starts_with(prefix)) m.erase(0, prefix.size());
    return m;
  }
  return {};
}

}  // namespace esc::compiler
