#pragma once
// A study: conditions compared together, each an experiment with some settings changed
// (`study NAME { conditions ... condition ... sweep ... }` in a script). Every condition
// runs with the study's master seed exactly as its experiment would with those settings
// (run r's seed from (master, r) alone), so conditions meet the same start poses and
// evaluation streams (common random numbers), and a condition's results do not depend on
// which other conditions the study holds.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "runtime/eval/experiment.hpp"

namespace esc::eval {

// A setting the study gives a condition, as written (`robot.time_constant` = `50ms`).
struct ConditionSetting {
  std::string key;
  std::string value;
  // A sweep's axis: where the value goes on a plot's x axis when every value of the axis is
  // a number in one unit (`25ms`, `50ms`: 25, 50 and "ms"); none for words and flags.
  bool swept = false;
  std::optional<double> x;
  std::string x_unit;
};

struct ConditionSpec {
  std::string name;                       // `no_inertia`, `time_constant=50ms`, an experiment's name
  std::string directory;                  // its files' directory in the study's (a file name)
  std::optional<int> sweep;               // the points of one `sweep` share its index
  std::vector<ConditionSetting> settings;
  ExperimentSpec experiment;              // with the study's runs and seed and these settings
};

struct StudySpec {
  std::string name;
  std::uint64_t seed = 1;                 // every condition's master seed
  std::vector<ConditionSpec> conditions;

  // The keys some condition sets and the conditions do not all resolve alike: a `--set` of
  // one would give every condition its value and flatten what the study compares. A key every
  // condition sets to one value (`generations 50` in each, to lengthen a study of short
  // experiments) varies nothing, and a `--set` of it shortens the whole study. A key some
  // condition does not resolve counts as varied.
  [[nodiscard]] std::vector<std::string> varied_keys() const {
    std::vector<std::string> keys;
    for (const ConditionSpec& c : conditions)
      for (const ConditionSetting& s : c.settings)
        if (std::find(keys.begin(), keys.end(), s.key) == keys.end() && resolved_apart(s.key)) keys.push_back(s.key);
    return keys;
  }

 private:
  [[nodiscard]] bool resolved_apart(const std::string& key) const {
    const std::string* first = nullptr;
    for (const ConditionSpec& c : conditions) {
      const auto it = c.experiment.resolved_settings.find(key);
      if (it == c.experiment.resolved_settings.end()) return true;
      if (first == nullptr) first = &it->second;
      else if (*first != it->second) return true;
    }
    return false;
  }
};

}  // namespace esc::eval
