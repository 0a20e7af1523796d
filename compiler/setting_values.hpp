#pragma once
// A setting's value as written (ast::Value) read as the kind a settings table row declares:
// a count, a quantity of a dimension, a flag, a word among choices, a range. Scripts and
// `esc run --set KEY=VALUE` read values through these functions, so both accept the same
// spellings and give the same messages, located at the value.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "compiler/units.hpp"

namespace esc::compiler {

// The text after `--set KEY=` as a value located at `where`: `on`, `off`, `true`, `false`, a
// word, `[LO, HI]` (a range), a list of another length (`[]`, `[0deg]`, `[90deg, 0deg,
// -90deg]`), or a number with an optional unit (`50ms`, `0.5 m/s^2`); nullopt when it is
// none of these.
[[nodiscard]] std::optional<ast::Value> value_from_text(std::string_view text, const SourceRange& where);

// A script's number (`epochs 10`) as a setting's value.
[[nodiscard]] ast::Value as_value(const ast::Quantity& q);

// A whole number without a unit in [min, max]; `name` is the setting (`epochs`).
[[nodiscard]] std::optional<long long> read_count(const ast::Value& v, std::string_view name, long long min,
                                                  long long max, Sink& sink);
// A seed: a whole number from 0 to 2^64 - 1 read from its digits (a double would round it
// above 2^53). A whole number written otherwise (`1e3`) is read as before, up to 2^53.
[[nodiscard]] std::optional<std::uint64_t> read_seed(const ast::Value& v, std::string_view name, Sink& sink);
// A quantity of dimension `dim` (Dim::None: a plain number), in SI.
[[nodiscard]] std::optional<double> read_quantity(const ast::Value& v, std::string_view name, Dim dim, Sink& sink);
// `on`/`true` or `off`/`false`.
[[nodiscard]] std::optional<bool> read_flag(const ast::Value& v, std::string_view name, Sink& sink);
// One of `words`: its index.
[[nodiscard]] std::optional<std::size_t> read_word(const ast::Value& v, std::string_view name,
                                                   const std::vector<std::string>& words, Sink& sink);
// `[LO, HI]` of plain numbers (not checked for LO < HI); `example` is shown in the help line
// (`[-1, 1]`).
[[nodiscard]] std::optional<std::pair<double, double>> read_range(const ast::Value& v, std::string_view name,
                                                                  std::string_view example, Sink& sink);

// A list of quantities of dimension `dim` in SI, as written in a script (`[90deg, 0deg]`, `[]`)
// or by `--set` (where a list of two reads as a range); `example` is shown in the help line.
[[nodiscard]] std::optional<std::vector<double>> read_list(const ast::Value& v, std::string_view name, Dim dim,
                                                           std::string_view example, Sink& sink);

// A list of tuples (`[(68deg, 90deg), (43deg, 45deg, 3.5cm)]`, `[]`), each of `dims.size()`
// quantities, the last `optional` of them may be left out; in SI, each of its dimension.
// `example` is shown in the help line.
struct TupleShape {
  std::span<const Dim> dims;
  std::size_t optional = 0;
  std::string_view example;
};
[[nodiscard]] std::optional<std::vector<std::vector<double>>> read_tuples(const ast::Value& v, std::string_view name,
                                                                          const TupleShape& shape, Sink& sink);

// What an option of `evolve es(...)` or `evolve gp(...)` is written with.
enum class OptionShape {
  Word,    // nothing: the option's name is the value (`comma`)
  Value,   // a number (`mu 30`)
  Range,   // a range (`bounds [-1, 1]`)
};
// Option `o` as a setting's value; a report instead when it is written with another shape
// (`mu` needs a value, `comma` takes no value, `bounds` takes a range), whose help shows
// `example` (the default value, `30`).
[[nodiscard]] std::optional<ast::Value> option_value(const ast::EsOption& o, OptionShape shape,
                                                     std::string_view example, Sink& sink);

}  // namespace esc::compiler
