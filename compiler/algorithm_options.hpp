#pragma once
// The options of every algorithm a script names beyond the paper's ES and GP (whose tables,
// es_options.hpp and gp_settings.hpp, keep their historic keys: `mu`, `gp.population`): one
// row per algorithm, read by its own option table (cmaes_options.hpp, ...) into
// ExperimentSpec::algorithm_settings[NAME]. A row gives `evolve NAME(...)`, `--set NAME.KEY`,
// the resolved settings `NAME.KEY` and the checks of its settings together. Adding an
// algorithm: its table, and a row in algorithm_options.cpp (docs/optimizers.md).
#include <any>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"

namespace esc::compiler {

struct AlgorithmOptions {
  std::string_view name;   // `evolve NAME(...)`, `by NAME`, `--set NAME.KEY`
  std::string_view what;   // in messages: "CMA-ES"
  // The algorithm's default settings.
  std::any (*defaults)() = nullptr;
  // `evolve NAME(...)`'s options into `settings` (the item's `for N generations` is the
  // experiment's, read by the caller); problems reported.
  void (*lower)(const ast::ExpItem& item, std::any& settings, Sink& sink) = nullptr;
  // Whether KEY (without `NAME.`) is one of its options; reading it into `settings`.
  bool (*has_key)(std::string_view key) = nullptr;
  bool (*set)(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) = nullptr;
  std::vector<std::string> (*keys)() = nullptr;   // its `--set` keys, without `NAME.`
  bool (*takes_range)(std::string_view key) = nullptr;
  // Its resolved settings, `NAME.KEY` -> text.
  void (*resolve)(const std::any& settings, std::map<std::string, std::string>& resolved) = nullptr;
  // A problem of the settings together for a network of `genome_size` weights, or "".
  std::string (*problem)(const std::any& settings, std::size_t genome_size) = nullptr;
};

[[nodiscard]] const std::vector<AlgorithmOptions>& further_algorithms();
[[nodiscard]] const AlgorithmOptions* find_further_algorithm(std::string_view name);

}  // namespace esc::compiler
