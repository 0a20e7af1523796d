#include "compiler/algorithm_options.hpp"

#include <limits>

#include <fmt/format.h>

#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using Row = OptionRow<OptionTarget>;
constexpr long long kIntMax = std::numeric_limits<int>::max();

OptionShape shape_of(evo::OptionForm f) {
  switch (f) {
    case evo::OptionForm::Word: return OptionShape::Word;
    case evo::OptionForm::Range:
    case evo::OptionForm::CountRange: return OptionShape::Range;
    case evo::OptionForm::Number:
    case evo::OptionForm::Count: break;
  }
  return OptionShape::Value;
}

// `[LO, HI]` of whole numbers of at least `least`, each end checked as a count is.
std::optional<std::pair<double, double>> read_count_range(const Row& o, const ast::Value& v, int least, Sink& sink) {
  if (!read_range(v, o.key, o.example, sink)) return std::nullopt;
  ast::Value lo = v, hi = v;
  lo.kind = hi.kind = ast::Value::Kind::Quantity;
  hi.q = v.hi;
  const auto first = read_count(lo, o.key, least, kIntMax, sink), last = read_count(hi, o.key, least, kIntMax, sink);
  if (!first || !last) return std::nullopt;
  return std::pair{static_cast<double>(*first), static_cast<double>(*last)};
}

// A value read as the runtime's row wants it (a plain number, a count, one of its words, a
// range), taken by the row (the experiment's generations by the compiler); its refusal
// reported at the value.
bool read(const Row& o, OptionTarget& t, const ast::Value& v, Sink& sink) {
  const evo::AlgorithmOption& a = *o.option;
  evo::OptionValue x;
  switch (a.form) {
    case evo::OptionForm::Number: {
      const auto q = read_quantity(v, o.key, Dim::None, sink);
      if (!q) return false;
      x.number = *q;
      break;
    }
    case evo::OptionForm::Count: {
      const auto n = read_count(v, o.key, a.least, kIntMax, sink);
      if (!n) return false;
      x.number = static_cast<double>(*n);
      break;
    }
    case evo::OptionForm::Word: {
      const auto i = read_word(v, o.key, o.words, sink);
      if (!i) return false;
      x.word = *i;
      break;
    }
    case evo::OptionForm::Range:
    case evo::OptionForm::CountRange: {
      const auto r = a.form == evo::OptionForm::Range ? read_range(v, o.key, o.example, sink)
                                                      : read_count_range(o, v, a.least, sink);
      if (!r) return false;
      x.lo = r->first;
      x.hi = r->second;
      break;
    }
  }
  if (a.experiments_generations) {
    *t.generations = static_cast<int>(x.number);
    return true;
  }
  const evo::OptionRefusal why = a.set(*t.settings, x);
  if (why.empty()) return true;
  Diagnostic& d = sink.error(v.where, why.names_option ? why.message : fmt::format("`{}` {}", o.key, why.message));
  if (!why.help.empty()) d.help.push_back(why.help);
  return false;
}

std::string text(const Row& o, const OptionTarget& t) {
  return o.option->experiments_generations ? std::to_string(*t.generations) : o.option->text(*t.settings);
}

const Row* generations_row(const std::vector<Row>& rows) { return find_option_word(rows, "generations"); }

}  // namespace

AlgorithmOptions::AlgorithmOptions(const evo::Algorithm& a)
    : name(a.name), what(a.what), scope(a.scope), group(a.bare_keys ? "" : std::string(a.name) + "."), algorithm_(&a) {
  const std::any d = a.defaults();
  for (const evo::AlgorithmOption& o : a.options()) {
    const bool range = o.form == evo::OptionForm::Range || o.form == evo::OptionForm::CountRange;
    rows_.push_back({o.key, shape_of(o.form), o.summary, &read, &text, o.words, !o.experiments_generations, &o,
                     range ? o.text(d) : std::string()});
  }
}

void AlgorithmOptions::lower(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink) const {
  const int errors = sink.errors();
  std::any& settings = settings_in(x);
  OptionTarget target{&settings, &x.generations};
  std::any shown = defaults();
  int shown_generations = eval::ExperimentSpec{}.generations;
  read_options(item, name, what, rows_, target, sink, OptionTarget{&shown, &shown_generations});
  if (generations_row(rows_) == nullptr && item.generations && item.generations->finite)
    if (const auto n = read_count(as_value(*item.generations), "generations", 1, kIntMax, sink))
      x.generations = static_cast<int>(*n);
  if (sink.errors() != errors) return;
  if (const evo::OptionRefusal c = conflict(settings); !c.empty()) {
    Diagnostic& d = sink.error(item.where, c.message);
    if (!c.help.empty()) d.help.push_back(c.help);
  }
}

bool AlgorithmOptions::has_key(std::string_view key) const { return find_option_key(rows_, key) != nullptr; }

bool AlgorithmOptions::set(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) const {
  const Row* o = find_option_key(rows_, key);
  OptionTarget target{&settings, nullptr};
  return o->read(*o, target, value, sink);
}

std::vector<std::string> AlgorithmOptions::keys() const { return option_keys(rows_); }

bool AlgorithmOptions::takes_range(std::string_view key) const {
  const Row* o = find_option_key(rows_, key);
  return o != nullptr && o->shape == OptionShape::Range;
}

void AlgorithmOptions::resolve(const std::any& settings, std::map<std::string, std::string>& resolved) const {
  for (const Row& o : rows_)
    if (o.own_key) resolved[group + std::string(o.key)] = o.option->text(settings);
}

void AlgorithmOptions::unresolve(std::map<std::string, std::string>& resolved) const {
  for (const Row& o : rows_)
    if (o.own_key) resolved.erase(group + std::string(o.key));
}

const std::vector<AlgorithmOptions>& algorithm_options() {
  static const std::vector<AlgorithmOptions> all = [] {
    std::vector<AlgorithmOptions> v;
    for (const evo::Algorithm& a : evo::algorithms()) v.emplace_back(a);
    return v;
  }();
  return all;
}

const AlgorithmOptions* find_algorithm_options(std::string_view name) {
  for (const AlgorithmOptions& a : algorithm_options())
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace esc::compiler
