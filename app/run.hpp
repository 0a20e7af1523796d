#pragma once
// Running an experiment or a study of a script into a directory, and continuing one that
// stopped: what `esc run` and `esc run --resume` do, and `esc.run`/`esc.resume` in Python.
// Progress and what is being done go to the events; a refusal is an app::Error, thrown
// before anything is written where it can be (a resume refused leaves every byte of its
// directory as it was).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/campaign_run.hpp"
#include "app/events.hpp"
#include "app/settings.hpp"
#include "compiler/compiler.hpp"
#include "runtime/eval/campaign.hpp"

namespace esc::app {

struct RunRequest {
  std::filesystem::path script;
  std::string experiment;        // an experiment or a study; empty: the first the script declares
  Overrides overrides;
  Execution execution;
  std::filesystem::path out;     // empty: runs/<name>-<local time>
};

struct ResumeRequest {
  std::filesystem::path dir;
  std::filesystem::path script;           // empty: the one the run started from
  std::optional<int> generations;         // carry every run on to this many generations
  std::filesystem::path cache;            // empty: the one the run used
  Execution execution;
  bool explain = false;                   // a refusal in full: diagnostics, the files that changed
};

// One experiment's campaign as it ended: the experiment run, or one condition of a study.
struct ConditionOutcome {
  std::string name;              // the condition's, or the experiment's
  eval::ExperimentSpec spec;
  eval::CampaignResult result;
};

struct Outcome {
  std::filesystem::path dir;
  std::string study;                          // empty for an experiment
  std::vector<ConditionOutcome> conditions;   // an experiment: one
  bool ran = true;                            // false: a resume found it complete
};

Outcome run(const RunRequest& request, const compiler::CompileOptions& options, Events& events);
Outcome resume(const ResumeRequest& request, const compiler::CompileOptions& options, Events& events);

}  // namespace esc::app
