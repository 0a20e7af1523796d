#pragma once
// Every algorithm's options, read from the table each algorithm keeps in its own folder
// (evo::Algorithm::options, runtime/evo/algorithm_options.hpp) into
// ExperimentSpec::algorithm_settings[NAME]: `evolve NAME(...)`, `--set NAME.KEY` (the ES's
// bare, `--set mu`), the resolved settings and the checks of its settings together, with the
// script's locations, units and "did you mean". Adding an algorithm changes nothing here
// (docs/optimizers.md).
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

// What an algorithm's options are read into: its settings, and the experiment's generations
// (the ES's historic `es(generations N)`; null where `--set` reads a key of its own).
struct OptionTarget {
  std::any* settings = nullptr;
  int* generations = nullptr;
};

class AlgorithmOptions {
 public:
  explicit AlgorithmOptions(const evo::Algorithm& a);

  std::string_view name;   // `evolve NAME(...)`, `by NAME`
  std::string_view what;   // in messages: "CMA-ES"
  evo::SettingsScope scope;
  // What its `--set` keys and resolved settings begin with: `NAME.`, or nothing for the ES's.
  std::string group;

  [[nodiscard]] std::any defaults() const { return algorithm_->defaults(); }
  // Its settings in `x` (x.algorithm_settings[NAME]), its defaults until something sets them.
  std::any& settings_in(eval::ExperimentSpec& x) const {
    return x.algorithm_settings.try_emplace(std::string(name), defaults()).first->second;
  }
  // Its settings that `x` holds, or null.
  [[nodiscard]] const std::any* held_by(const eval::ExperimentSpec& x) const {
    const auto it = x.algorithm_settings.find(std::string(name));
    return it == x.algorithm_settings.end() ? nullptr : &it->second;
  }
  [[nodiscard]] std::any* held_by(eval::ExperimentSpec& x) const {
    const auto it = x.algorithm_settings.find(std::string(name));
    return it == x.algorithm_settings.end() ? nullptr : &it->second;
  }
  // `evolve NAME(...) [for N generations]` into its settings in `x` and, unless it has a
  // `generations` option of its own (GP's), the experiment's generations; then its options
  // that do not go together, at the item. Problems reported.
  void lower(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink) const;
  // Whether KEY (without the group) is one of its `--set` keys; reading a value of it.
  [[nodiscard]] bool has_key(std::string_view key) const;
  bool set(std::any& settings, std::string_view key, const ast::Value& value, Sink& sink) const;
  [[nodiscard]] std::vector<std::string> keys() const;   // without the group
  [[nodiscard]] bool takes_range(std::string_view key) const;
  // Its resolved settings, group + KEY -> text; and those keys erased.
  void resolve(const std::any& settings, std::map<std::string, std::string>& resolved) const;
  void unresolve(std::map<std::string, std::string>& resolved) const;
  // A problem of the settings together for `problem` (a network's size, the declared
  // objectives and descriptors), or "".
  [[nodiscard]] std::string problem(const std::any& settings, const evo::Problem& problem) const {
    return algorithm_->problem(settings, problem);
  }
  // Options of the settings that do not go together, whatever they evolve; empty if none.
  [[nodiscard]] evo::OptionRefusal conflict(const std::any& settings) const { return algorithm_->conflict(settings); }

 private:
  const evo::Algorithm* algorithm_;
  std::vector<OptionRow<OptionTarget>> rows_;
};

// Every registered algorithm's, in the registry's order.
[[nodiscard]] const std::vector<AlgorithmOptions>& algorithm_options();
[[nodiscard]] const AlgorithmOptions* find_algorithm_options(std::string_view name);

}  // namespace esc::compiler
