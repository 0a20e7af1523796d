#include "app/run_evaluations.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/error.hpp"

namespace esc::app {

namespace {

// Keeps what every candidate measured, in the script's own signs; passes the run's events on.
class Recorder final : public eval::CampaignListener {
 public:
  Recorder(const eval::ExperimentSpec& spec, RunEvaluations& into, eval::CampaignListener* next)
      : spec_(&spec), into_(&into), next_(next) {}

  void round_progress(const eval::RoundProgress& p) override {
    if (next_ != nullptr) next_->round_progress(p);
  }
  void round_evaluated(const eval::RoundStats& round) override {
    if (next_ != nullptr) next_->round_evaluated(round);
  }
  void candidates_evaluated(const control::ControllerSpec& c, int run, int generation,
                            std::span<const evo::Outcome> outcomes) override {
    for (std::size_t k = 0; k < outcomes.size(); ++k) {
      const evo::Outcome& o = outcomes[k];
      into_->generation.push_back(generation);
      into_->candidate.push_back(static_cast<int>(k));
      for (std::size_t i = 0; i < o.objectives.size(); ++i) into_->values.push_back(spec_->as_declared(i, o.objectives[i]));
      into_->values.insert(into_->values.end(), o.descriptors.begin(), o.descriptors.end());
    }
    if (next_ != nullptr) next_->candidates_evaluated(c, run, generation, outcomes);
  }
  void generation_done(const control::ControllerSpec& c, int run, const eval::GenerationStats& g) override {
    if (next_ != nullptr) next_->generation_done(c, run, g);
  }

 private:
  const eval::ExperimentSpec* spec_;
  RunEvaluations* into_;
  eval::CampaignListener* next_;
};

// The first generation whose statistics differ, or empty when the runs are the same.
std::string first_difference(const eval::RunResult& again, const eval::RunResult& stored) {
  const std::size_t n = std::min(again.generations.size(), stored.generations.size());
  for (std::size_t g = 0; g < n; ++g) {
    const eval::GenerationStats& a = again.generations[g];
    const eval::GenerationStats& b = stored.generations[g];
    if (a.best != b.best || a.mean != b.mean || a.sd != b.sd || a.evaluations != b.evaluations)
      return fmt::format("generation {} has a best of {:.17g} and a mean of {:.17g}, stored {:.17g} and {:.17g}", g,
                         a.best, a.mean, b.best, b.mean);
  }
  if (again.generations.size() != stored.generations.size())
    return fmt::format("it ran {} generations, the stored run {}", again.generations.size(), stored.generations.size());
  return {};
}

}  // namespace

RunEvaluations run_evaluations(const StoredRun& stored, const eval::ExperimentSpec& ran, const std::string& controller,
                               int run, int threads, eval::CampaignListener* progress) {
  const eval::RunResult& finished = *finished_run(stored, controller, run).run;
  // The one controller: each run's seed depends on its index alone, not on what else runs.
  eval::ExperimentSpec spec = ran;
  std::erase_if(spec.controllers, [&](const control::ControllerSpec& x) { return x.name != controller; });
  if (spec.controllers.empty())
    throw Error(ErrorKind::Results, fmt::format("experiment `{}` compares no controller `{}`", spec.name, controller));

  RunEvaluations out;
  out.objectives.push_back(spec.fitness.name);
  for (const auto& f : spec.further) out.objectives.push_back(f.name);
  for (const eval::DescriptorSpec& d : spec.descriptors) {
    out.descriptors.push_back(d.name);
    out.descriptor_ranges.push_back(d.range);
  }
  Recorder recorder(spec, out, progress);
  eval::CampaignOptions options;
  options.threads = threads;
  options.only_runs = {run};
  eval::CampaignResult again;
  try {
    again = eval::run_campaign(spec, options, recorder);
  } catch (const std::invalid_argument& e) {
    throw Error(ErrorKind::Results, e.what());
  }
  const std::string difference =
      first_difference(again.controllers.front().runs[static_cast<std::size_t>(run)], finished);
  if (!difference.empty())
    throw Error(ErrorKind::Results,
                fmt::format("run {} of {} made again is not the stored run: {}", run + 1, controller, difference),
                "the simulation or the optimizer has changed since the run was made");
  return out;
}

}  // namespace esc::app
