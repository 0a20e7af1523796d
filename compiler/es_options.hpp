#pragma once
// The options of `evolve es(...)` (runtime/evo/es/es.hpp's EsSettings): one table for scripts,
// `esc run --set KEY=VALUE`, resolved settings and the documentation, with one spelling per
// value (a choice's words, `comma`, `no_recombination`, are written alone in `es(...)` and
// as `--set selection=comma`), and every check of ES settings: each option's own value
// (its row) and the ones that relate options (es_problem).
#include <optional>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/option_table.hpp"
#include "compiler/sink.hpp"
#include "runtime/evo/es/es.hpp"

namespace esc::compiler {

using EsOption = OptionRow<evo::EsSettings>;

[[nodiscard]] const std::vector<EsOption>& es_options();

// A problem between options (comma selection needs lambda >= mu), or nullopt.
struct EsProblem {
  std::string message, help;
};
[[nodiscard]] std::optional<EsProblem> es_problem(const evo::EsSettings& s);

// `evolve es(...) [for N generations]` -> `es`; problems reported.
void lower_es_item(const ast::ExpItem& item, evo::EsSettings& es, Sink& sink);

}  // namespace esc::compiler
