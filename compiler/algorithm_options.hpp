#pragma once
// The options of every algorithm beyond the paper's ES and GP (whose tables, es_options.hpp
// and gp_settings.hpp, keep their historic keys: `mu`, `gp.population`), read from the table
// each algorithm keeps in its own folder (evo::Algorithm::options, runtime/evo/
// algorithm_options.hpp) into ExperimentSpec::algorithm_settings[NAME]: `evolve NAME(...)`,
// `--set NAME.KEY`, the resolved settings `NAME.KEY` and the checks of its settings together,
// with the script's locations, units and "did you mean". Adding an algorithm changes nothing
// here (docs/optimizers.md).
#include <any>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/option_table.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/evo/registry.hpp"

namespace esc::compiler {

class AlgorithmOptions {
 public:
  explicit AlgorithmOptions(const evo::Algorithm& a);

  std::string_view name;   // `evolve NAME(...)`, `by NAME`, `--set NAME.KEY`
  std::string_view what;   // in messages: "CMA-ES"

  [[nodiscard]] std::any defaults() const { return algorithm_->defaults(); }
  // Its settings in `x` (x.algorithm_settings[NAME]), its defaults until something sets them.
  std::any& settings_in(eval::ExperimentSpec& x) const {
    return x.algorithm_settings.try_emplace(std::string(name), defaults()).first->second;
  }
  // `evolve NAME(...)`'s options into `settings` (the item's `for N generations` is the
  // experiment's, read by the caller); problems reported.
  void lower(const ast::ExpItem& item, std::any& settings, Sink& sink) const;
  // Whether KEY (without `NAME.`) is one of its options; reading a value of it.
  [[nodiscard]] bool has_key(std::string_view key) const;
  bool set(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) const;
  [[nodiscard]] std::vector<std::string> keys() const;   // without `NAME.`
  [[nodiscard]] bool takes_range(std::string_view key) const;
  // Its resolved settings, `NAME.KEY` -> text.
  void resolve(const std::any& settings, std::map<std::string, std::string>& resolved) const;
  // A problem of the settings together for `problem` (a network's size, the declared
  // objectives and descriptors), or "".
  [[nodiscard]] std::string problem(const std::any& settings, const evo::Problem& problem) const {
    return algorithm_->problem(settings, problem);
  }

 private:
  const evo::Algorithm* algorithm_;
  std::vector<OptionRow<std::any>> rows_;
};

[[nodiscard]] const std::vector<AlgorithmOptions>& further_algorithms();
[[nodiscard]] const AlgorithmOptions* find_further_algorithm(std::string_view name);

}  // namespace esc::compiler
