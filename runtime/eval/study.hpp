#pragma once
// A study: conditions compared together, each an experiment with some settings changed
// (`study NAME { conditions ... condition ... sweep ... }` in a script). Every condition
// runs with the study's master seed exactly as its experiment would with those settings
// (run r's seed from (master, r) alone), so conditions meet the same start poses and
// evaluation streams (common random numbers), and a condition's results do not depend on
// which other conditions the study holds.
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
};

}  // namespace esc::eval
