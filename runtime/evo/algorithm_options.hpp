#pragma once
// An algorithm's options in the runtime's own terms, so that the table lives in the
// algorithm's folder and the compiler reads every algorithm's options alike: each option's
// key (in `evolve NAME(...)`, `--set NAME.KEY` and the resolved settings; the ES's bare,
// `--set mu`, as the paper's scripts wrote them), how it is written (a number, a whole number,
// one of its words written alone, a range [LO, HI] of numbers or of whole numbers), what it
// means, how a value is taken (the refusal says why one is not: the compiler reports it at
// the value, with the script's location) and its text.
#include <any>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace esc::evo {

// Count and CountRange are whole numbers of at least AlgorithmOption::least (at most the
// largest int), checked as the compiler checks every count (`epochs`), in its words.
enum class OptionForm { Number, Count, Word, Range, CountRange };

// A value as the compiler read it: a plain number (a count too), the index of a word, or a
// range.
struct OptionValue {
  double number = 0.0;
  std::size_t word = 0;
  double lo = 0.0, hi = 0.0;
};

// Why a value is not taken; empty when it is. The compiler reports `message` at the value
// after the option's key (`\`sigma\` must be ...`), or alone where `names_option` says it
// names the option itself (the ES's historic `empty bounds: ...`), with `help` as its help.
struct OptionRefusal {
  std::string message;
  std::string help = {};
  bool names_option = false;

  OptionRefusal() = default;
  // One sentence that follows the key: what most rows refuse with.
  OptionRefusal(std::string why) : message(std::move(why)) {}   // NOLINT(google-explicit-constructor)
  OptionRefusal(std::string why, std::string what_to_do, bool names)
      : message(std::move(why)), help(std::move(what_to_do)), names_option(names) {}
  [[nodiscard]] bool empty() const noexcept { return message.empty(); }
};

// When an experiment holds an algorithm's settings, and so when its resolved settings list
// them and what `--set` of one of its keys does in an experiment that holds none.
enum class SettingsScope {
  // Where it evolves a compared controller (CMA-ES, ...): `--set` makes its settings (a
  // `--set networks=` may follow), resolved only where it evolves one, so that runs from
  // before it keep their settings.
  InUse,
  // Where the script gives them (`evolve gp`): GP's are every tree's operators, whichever
  // algorithm selects; `--set` checks a value and drops it in an experiment without them.
  Given,
  // In every experiment: the ES's, which evolve the networks unless the script names another
  // algorithm; the paper's runs always listed them.
  Always,
};

struct AlgorithmOption {
  std::string_view key;
  OptionForm form = OptionForm::Number;
  std::string_view summary;
  std::vector<std::string> words = {};   // Word: its choices, in the order `set` numbers them
  // Takes `v` into the settings (the algorithm's own type, in the std::any); empty when taken.
  OptionRefusal (*set)(std::any& settings, const OptionValue& v) = nullptr;
  std::string (*text)(const std::any& settings) = nullptr;
  int least = 0;   // Count, CountRange: the smallest whole number taken
  // The experiment's generations written among the options (the ES's historic `es(generations
  // N)`, as `for N generations`): a Count read into the experiment, with no `--set` key of
  // the algorithm's, no set and no text.
  bool experiments_generations = false;
};

// Row helpers over a settings type's fields.
// Why settings cannot run, from checks that throw (an algorithm's own constructor or
// validation): the std::invalid_argument's message without `prefix` (the algorithm's
// "CMA-ES: ", which the compiler's message names already), or "" when `check` throws none.
// What the value types' problem() return.
template <class Check>
[[nodiscard]] std::string rejection(Check&& check, std::string_view prefix = {}) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    std::string m = e.what();
    if (m.starts_with(prefix)) m.erase(0, prefix.size());
    return m;
  }
  return {};
}

namespace option {

inline std::string number(double v) { return fmt::format("{}", v); }

// A whole number in [Min, Max] into an int field.
template <class S, int S::*Field, int Min, int Max>
OptionRefusal whole(std::any& s, const OptionValue& v) {
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
OptionRefusal real(std::any& s, const OptionValue& v) {
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
OptionRefusal two_words(std::any& s, const OptionValue& v) {
  std::any_cast<S&>(s).*Field = v.word == 1;
  return {};
}

// `bounds [LO, HI]` within +-Bound into the `lower` and `upper` fields.
template <class S, const double* Bound>
OptionRefusal bounds(std::any& s, const OptionValue& v) {
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

// A whole number the compiler checked (a Count, of at least the row's `least`) into an int
// field: of the settings or of a base they extend (GP's, the tree operators).
template <class S, auto Field>
OptionRefusal count(std::any& s, const OptionValue& v) {
  std::any_cast<S&>(s).*Field = static_cast<int>(v.number);
  return {};
}
template <class S, auto Field>
std::string count_text(const std::any& s) {
  return std::to_string(std::any_cast<const S&>(s).*Field);
}

// What a plain number must be, in the words of the compiler's other settings.
enum class Sign { Probability, Positive, NonNegative };

// A plain number of that kind, at most *Max where given, into a double field; its text.
template <class S, auto Field, Sign K, const double* Max = nullptr>
OptionRefusal signed_real(std::any& s, const OptionValue& v) {
  const double x = v.number;
  if (K == Sign::Probability && !(x >= 0.0 && x <= 1.0))
    return fmt::format("is a probability in [0, 1], found {}", number(x));
  if (K == Sign::Positive && !(x > 0.0)) return fmt::format("must be greater than 0, found {}", number(x));
  if (K == Sign::NonNegative && !(x >= 0.0)) return fmt::format("must be at least 0, found {}", number(x));
  if constexpr (Max != nullptr)
    if (x > *Max) return fmt::format("must be at most {}, found {}", number(*Max), number(x));
  std::any_cast<S&>(s).*Field = x;
  return {};
}
template <class S, auto Field>
std::string signed_real_text(const std::any& s) {
  return number(std::any_cast<const S&>(s).*Field);
}

// One of the words into an enum field whose values number them in order; its text.
template <class S, auto Field>
OptionRefusal choice(std::any& s, const OptionValue& v) {
  auto& field = std::any_cast<S&>(s).*Field;
  field = static_cast<std::remove_reference_t<decltype(field)>>(v.word);
  return {};
}
template <class S, auto Field, const std::vector<std::string>& Words>
std::string choice_text(const std::any& s) {
  return Words[static_cast<std::size_t>(std::any_cast<const S&>(s).*Field)];
}

}  // namespace option

}  // namespace esc::evo
