#pragma once
// An algorithm's options in the runtime's own terms, so that the table lives in the
// algorithm's folder and the compiler reads every algorithm's options alike: each option's
// key (in `evolve NAME(...)`, `--set NAME.KEY` and the resolved settings), how it is written
// (a number, one of its words written alone, or a range [LO, HI]), what it means, how a value
// is taken (the message says why one is not: the compiler reports it at the value, with the
// script's location) and its text. The paper's ES and GP keep their historic tables
// (compiler/es_options.*, gp_settings.*) and keys (`mu`, `gp.population`).
#include <any>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace esc::evo {

enum class OptionForm { Number, Word, Range };

// A value as the compiler read it: a plain number, the index of a word, or a range.
struct OptionValue {
  double number = 0.0;
  std::size_t word = 0;
  double lo = 0.0, hi = 0.0;
};

struct AlgorithmOption {
  std::string_view key;
  OptionForm form = OptionForm::Number;
  std::string_view summary;
  std::vector<std::string> words = {};   // Word: its choices, in the order `set` numbers them
  // Takes `v` into the settings (the algorithm's own type, in the std::any); "" when taken,
  // else why not, in one sentence naming the option.
  std::string (*set)(std::any& settings, const OptionValue& v) = nullptr;
  std::string (*text)(const std::any& settings) = nullptr;
};

// Row helpers over a settings type's fields.
namespace option {

inline std::string number(double v) { return fmt::format("{}", v); }

// A whole number in [Min, Max] into an int field.
template <class S, int S::*Field, int Min, int Max>
std::string whole(std::any& s, const OptionValue& v) {
  if (!(v.number == std::floor(v.number) && v.number >= Min && v.number <= Max))
    return fmt::format("must be a whole number in [{}, {}], found {}", Min, Max, number(v.number));
  std::any_cast<S&>(s).*Field = static_cast<int>(v.number);
  return {};
}
template <class S, int S::*Field>
std::string whole_text(const std::any& s) {
  return std::to_string(std::any_cast<const S&>(s).*Field);
}

// A number between *Min and *Max into a double field; each end excluded when its flag says.
template <class S, double S::*Field, const double* Min, bool AboveMin, const double* Max, bool BelowMax>
std::string real(std::any& s, const OptionValue& v) {
  const bool low_ok = AboveMin ? v.number > *Min : v.number >= *Min;
  const bool high_ok = BelowMax ? v.number < *Max : v.number <= *Max;
  if (!(low_ok && high_ok))
    return fmt::format("must be in {}{}, {}{}, found {}", AboveMin ? "(" : "[", number(*Min), number(*Max),
                       BelowMax ? ")" : "]", number(v.number));
  std::any_cast<S&>(s).*Field = v.number;
  return {};
}
template <class S, double S::*Field>
std::string real_text(const std::any& s) {
  return number(std::any_cast<const S&>(s).*Field);
}

// A choice of two words into a bool field: the first false, the second true.
template <class S, bool S::*Field>
std::string two_words(std::any& s, const OptionValue& v) {
  std::any_cast<S&>(s).*Field = v.word == 1;
  return {};
}

// `bounds [LO, HI]` within +-Bound into the `lower` and `upper` fields.
template <class S, const double* Bound>
std::string bounds(std::any& s, const OptionValue& v) {
  if (std::abs(v.lo) > *Bound || std::abs(v.hi) > *Bound)
    return fmt::format("must lie within [-{0}, {0}], found [{1}, {2}]", number(*Bound), number(v.lo), number(v.hi));
  if (!(v.lo < v.hi))
    return fmt::format("is empty: the lower bound ({}) must be below the upper ({})", number(v.lo), number(v.hi));
  std::any_cast<S&>(s).lower = v.lo;
  std::any_cast<S&>(s).upper = v.hi;
  return {};
}
template <class S>
std::string bounds_text(const std::any& s) {
  const S& x = std::any_cast<const S&>(s);
  return fmt::format("[{}, {}]", number(x.lower), number(x.upper));
}

}  // namespace option

}  // namespace esc::evo
