#include "compiler/algorithm_options.hpp"

#include <fmt/format.h>

#include "compiler/quantities.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using Row = OptionRow<std::any>;

OptionShape shape_of(evo::OptionForm f) {
  switch (f) {
    case evo::OptionForm::Word: return OptionShape::Word;
    case evo::OptionForm::Range: return OptionShape::Range;
    case evo::OptionForm::Number: break;
  }
  return OptionShape::Value;
}

// A value read as the runtime's row wants it (a plain number, one of its words, a range),
// taken by the row; its refusal reported at the value.
bool read(const Row& o, std::any& s, const ast::Value& v, Sink& sink) {
  const evo::AlgorithmOption& a = *o.option;
  evo::OptionValue x;
  switch (a.form) {
    case evo::OptionForm::Number: {
      const auto q = read_quantity(v, o.key, Dim::None, sink);
      if (!q) return false;
      x.number = *q;
      break;
    }
    case evo::OptionForm::Word: {
      const auto i = read_word(v, o.key, o.words, sink);
      if (!i) return false;
      x.word = *i;
      break;
    }
    case evo::OptionForm::Range: {
      const auto r = read_range(v, o.key, "[-1, 1]", sink);
      if (!r) return false;
      x.lo = r->first;
      x.hi = r->second;
      break;
    }
  }
  if (std::string why = a.set(s, x); !why.empty()) {
    sink.error(v.where, fmt::format("`{}` {}", o.key, why));
    return false;
  }
  return true;
}

std::string text(const Row& o, const std::any& s) { return o.option->text(s); }

}  // namespace

AlgorithmOptions::AlgorithmOptions(const evo::Algorithm& a) : name(a.name), what(a.what), algorithm_(&a) {
  for (const evo::AlgorithmOption& o : a.options())
    rows_.push_back({o.key, shape_of(o.form), o.summary, &read, &text, o.words, true, &o});
}

void AlgorithmOptions::lower(const ast::ExpItem& item, std::any& settings, Sink& sink) const {
  ast::ExpItem options = item;
  options.generations.reset();
  read_options(options, name, what, rows_, settings, sink, defaults());
}

bool AlgorithmOptions::has_key(std::string_view key) const { return find_option_key(rows_, key) != nullptr; }

bool AlgorithmOptions::set(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) const {
  const Row* o = find_option_key(rows_, key);
  return o->read(*o, settings, value, sink);
}

std::vector<std::string> AlgorithmOptions::keys() const { return option_keys(rows_); }

bool AlgorithmOptions::takes_range(std::string_view key) const {
  const Row* o = find_option_key(rows_, key);
  return o != nullptr && o->shape == OptionShape::Range;
}

void AlgorithmOptions::resolve(const std::any& settings, std::map<std::string, std::string>& resolved) const {
  for (const Row& o : rows_) resolved[fmt::format("{}.{}", name, o.key)] = o.text(o, settings);
}

const std::vector<AlgorithmOptions>& further_algorithms() {
  static const std::vector<AlgorithmOptions> all = [] {
    std::vector<AlgorithmOptions> v;
    for (const evo::Algorithm& a : evo::algorithms())
      if (!a.options().empty()) v.emplace_back(a);
    return v;
  }();
  return all;
}

const AlgorithmOptions* find_further_algorithm(std::string_view name) {
  for (const AlgorithmOptions& a : further_algorithms())
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace esc::compiler
