#include "compiler/setting_values.hpp"

#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "runtime/core/seed_text.hpp"

namespace esc::compiler {

namespace {

std::string_view trimmed(std::string_view t) {
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return t;
}

bool is_word(std::string_view t) {
  if (t.empty() || !(std::isalpha(static_cast<unsigned char>(t[0])) != 0 || t[0] == '_')) return false;
  for (const char c : t)
    if (!(std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_')) return false;
  return true;
}

std::optional<ast::Quantity> quantity_from_text(std::string_view text, const SourceRange& where) {
  ast::Quantity q;
  if (!split_value(text, q.value, q.unit)) return std::nullopt;
  // The number as written: the text without its unit (split_value drops the spaces inside it).
  std::string_view number = trimmed(text);
  std::size_t kept = number.size();
  for (std::size_t left = q.unit.size(); left > 0 && kept > 0; --kept)
    if (number[kept - 1] != ' ' && number[kept - 1] != '\t') --left;
  q.text = std::string(trimmed(number.substr(0, kept)));
  if (!q.text.empty() && q.text.front() == '+') q.text.erase(0, 1);
  q.where = q.unit_where = where;
  return q;
}

// Quantities separated by commas: false when one is not a quantity.
bool quantities_from_text(std::string_view text, const SourceRange& where, std::vector<ast::Quantity>& out) {
  for (;;) {
    const std::size_t comma = text.find(',');
    auto q = quantity_from_text(text.substr(0, comma), where);
    if (!q) return false;
    out.push_back(std::move(*q));
    if (comma == std::string_view::npos) return true;
    text.remove_prefix(comma + 1);
  }
}

// `(a, b), (c, d)`: false unless it is tuples of quantities separated by commas.
bool tuples_from_text(std::string_view text, const SourceRange& where, std::vector<ast::QuantityTuple>& out) {
  for (;;) {
    text = trimmed(text);
    const std::size_t close = text.find(')');
    if (text.empty() || text.front() != '(' || close == std::string_view::npos) return false;
    ast::QuantityTuple& t = out.emplace_back();
    t.where = where;
    if (!quantities_from_text(text.substr(1, close - 1), where, t.items)) return false;
    text = trimmed(text.substr(close + 1));
    if (text.empty()) return true;
    if (text.front() != ',') return false;
    text.remove_prefix(1);
  }
}

// "`on`", "`[1, 2]`": a value as the user wrote it, for messages.
std::string shown(const ast::Value& v) { return fmt::format("`{}`", v.text); }

}  // namespace

std::optional<ast::Value> value_from_text(std::string_view text_in, const SourceRange& where) {
  const std::string_view text = trimmed(text_in);
  ast::Value v;
  v.text = std::string(text);
  v.where = where;
  if (text == "on" || text == "off" || text == "true" || text == "false") {
    v.kind = ast::Value::Kind::Bool;
    v.flag = text == "on" || text == "true";
    return v;
  }
  if (is_word(text)) {
    v.kind = ast::Value::Kind::Word;
    return v;
  }
  if (text.size() >= 2 && text.front() == '[' && text.back() == ']') {
    const std::string_view inner = trimmed(text.substr(1, text.size() - 2));
    if (!inner.empty() && inner.front() == '(') {
      if (!tuples_from_text(inner, where, v.tuples)) return std::nullopt;
      v.kind = ast::Value::Kind::Tuples;
      return v;
    }
    if (!inner.empty() && !quantities_from_text(inner, where, v.list)) return std::nullopt;
    if (v.list.size() != 2) {
      v.kind = ast::Value::Kind::List;
      return v;
    }
    v.kind = ast::Value::Kind::Range;
    v.q = std::move(v.list[0]);
    v.hi = std::move(v.list[1]);
    v.list.clear();
    return v;
  }
  auto q = quantity_from_text(text, where);
  if (!q) return std::nullopt;
  v.kind = ast::Value::Kind::Quantity;
  v.q = std::move(*q);
  return v;
}

ast::Value as_value(const ast::Quantity& q) {
  ast::Value v;
  v.kind = ast::Value::Kind::Quantity;
  v.q = q;
  v.text = q.text + q.unit;
  v.where = q.where;
  return v;
}

std::optional<long long> read_count(const ast::Value& v, std::string_view name, long long min, long long max,
                                    Sink& sink) {
  if (v.kind != ast::Value::Kind::Quantity) {
    sink.error(v.where, fmt::format("`{}` takes a whole number, found {}", name, shown(v)));
    return std::nullopt;
  }
  return to_whole(v.q, fmt::format("`{}`", name), min, max, sink);
}

std::optional<std::uint64_t> read_seed(const ast::Value& v, std::string_view name, Sink& sink) {
  if (v.kind == ast::Value::Kind::Quantity && v.q.unit.empty())
    if (const auto s = parse_seed(v.q.text)) return s;
  const bool digits = v.kind == ast::Value::Kind::Quantity && v.q.text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits && v.kind == ast::Value::Kind::Quantity && v.q.unit.empty() && v.q.finite && v.q.value >= 0.0 &&
      v.q.value <= 0x1p53 && v.q.value == std::floor(v.q.value))
    return static_cast<std::uint64_t>(v.q.value);
  sink.error(v.where, fmt::format("`{}` is {}, found {}", name, kSeedRange, shown(v)));
  return std::nullopt;
}

std::optional<double> read_quantity(const ast::Value& v, std::string_view name, Dim dim, Sink& sink) {
  if (v.kind != ast::Value::Kind::Quantity) {
    sink.error(v.where, fmt::format("`{}` takes {}, found {}", name, dim_phrase(dim), shown(v)));
    return std::nullopt;
  }
  return to_si(v.q, dim, sink);
}

std::optional<bool> read_flag(const ast::Value& v, std::string_view name, Sink& sink) {
  if (v.kind == ast::Value::Kind::Bool) return v.flag;
  sink.error(v.where, fmt::format("`{}` is `on` or `off`, found {}", name, shown(v)))
      .help.push_back(fmt::format("write `{} on` or `{} off`", name, name));
  return std::nullopt;
}

std::optional<std::size_t> read_word(const ast::Value& v, std::string_view name, const std::vector<std::string>& words,
                                     Sink& sink) {
  if (v.kind == ast::Value::Kind::Word)
    for (std::size_t i = 0; i < words.size(); ++i)
      if (words[i] == v.text) return i;
  Diagnostic& d = sink.error(v.where, fmt::format("`{}` is {}, found {}", name, quoted_list(words), shown(v)));
  if (v.kind == ast::Value::Kind::Word) suggest(d, v.text, words);
  return std::nullopt;
}

std::optional<std::pair<double, double>> read_range(const ast::Value& v, std::string_view name,
                                                    std::string_view example, Sink& sink) {
  if (v.kind != ast::Value::Kind::Range) {
    sink.error(v.where, fmt::format("`{}` takes a range, as in `{}`, found {}", name, example, shown(v)))
        .help.push_back(fmt::format("write `{} {}`", name, example));
    return std::nullopt;
  }
  const auto lo = to_si(v.q, Dim::None, sink);
  const auto hi = to_si(v.hi, Dim::None, sink);
  if (!lo || !hi) return std::nullopt;
  return std::pair{*lo, *hi};
}

std::optional<std::vector<double>> read_list(const ast::Value& v, std::string_view name, Dim dim,
                                             std::string_view example, Sink& sink) {
  std::vector<ast::Quantity> items = v.list;
  if (v.kind == ast::Value::Kind::Range) items = {v.q, v.hi};
  if (v.kind != ast::Value::Kind::List && v.kind != ast::Value::Kind::Range) {
    sink.error(v.where, fmt::format("`{}` takes a list, each value {}, as in `{}`, found {}", name, dim_phrase(dim),
                                    example, shown(v)))
        .help.push_back(fmt::format("write `{} {}`", name, example));
    return std::nullopt;
  }
  std::vector<double> out;
  for (const ast::Quantity& q : items) {
    if (!q.finite) return std::nullopt;   // reported by the parser
    const auto x = to_si(q, dim, sink);
    if (!x) return std::nullopt;
    out.push_back(*x);
  }
  return out;
}

std::optional<std::vector<std::vector<double>>> read_tuples(const ast::Value& v, std::string_view name,
                                                                const TupleShape& shape, Sink& sink) {
  const bool empty = (v.kind == ast::Value::Kind::List && v.list.empty());
  if (v.kind != ast::Value::Kind::Tuples && !empty) {
    sink.error(v.where, fmt::format("`{}` takes a list of tuples, as in `{}`, found {}", name, shape.example, shown(v)))
        .help.push_back(fmt::format("write `{} {}`", name, shape.example));
    return std::nullopt;
  }
  const std::size_t most = shape.dims.size();
  const std::size_t least = most - shape.optional;
  std::vector<std::vector<double>> out;
  for (const ast::QuantityTuple& t : v.tuples) {
    if (t.items.size() < least || t.items.size() > most) {
      const std::string count = least == most ? std::to_string(most) : fmt::format("{} or {}", least, most);
      sink.error(t.where, fmt::format("each tuple of `{}` holds {} values, this one {}", name, count, t.items.size()))
          .help.push_back(fmt::format("write `{} {}`", name, shape.example));
      return std::nullopt;
    }
    std::vector<double>& row = out.emplace_back();
    for (std::size_t i = 0; i < t.items.size(); ++i) {
      if (!t.items[i].finite) return std::nullopt;   // reported by the parser
      const auto x = to_si(t.items[i], shape.dims[i], sink);
      if (!x) return std::nullopt;
      row.push_back(*x);
    }
  }
  return out;
}

std::optional<ast::Value> option_value(const ast::EsOption& o, OptionShape shape, std::string_view example,
                                       Sink& sink) {
  const std::string& n = o.name.text;
  const OptionShape written = o.lo ? OptionShape::Range : o.value ? OptionShape::Value : OptionShape::Word;
  if (written != shape) {
    if (shape == OptionShape::Word)
      sink.error(o.where, fmt::format("`{}` takes no value", n)).help.push_back(fmt::format("write `{}`", n));
    else
      sink.error(o.where, fmt::format("`{}` {}", n, shape == OptionShape::Range ? "takes a range" : "needs a value"))
          .help.push_back(fmt::format("write `{} {}`", n, example));
    return std::nullopt;
  }
  ast::Value v;
  switch (shape) {
    case OptionShape::Word:
      v.kind = ast::Value::Kind::Word;
      v.text = n;
      v.where = o.name.where;
      break;
    case OptionShape::Value: v = as_value(*o.value); break;
    case OptionShape::Range:
      v.kind = ast::Value::Kind::Range;
      v.q = *o.lo;
      v.hi = *o.hi;
      v.text = fmt::format("[{}, {}]", o.lo->text, o.hi->text);
      v.where = o.where;
      break;
  }
  return v;
}

}  // namespace esc::compiler
