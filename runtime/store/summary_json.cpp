#include "runtime/store/summary_json.hpp"

namespace esc::store {

nlohmann::ordered_json summary_json(const eval::CampaignResult& result) {
  nlohmann::ordered_json controllers = nlohmann::ordered_json::object();
  for (const auto& c : result.controllers) {
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto& r : c.runs) {
      nlohmann::ordered_json best = nlohmann::ordered_json::array();
      nlohmann::ordered_json mean = nlohmann::ordered_json::array();
      nlohmann::ordered_json sd = nlohmann::ordered_json::array();
      for (const auto& g : r.generations) {
        best.push_back(g.best);
        mean.push_back(g.mean);
        sd.push_back(g.sd);
      }
      nlohmann::ordered_json run = {{"run", r.run + 1}, {"seed", r.seed}, {"best_fitness", r.best_fitness},
                                    {"best", best}, {"mean", mean}, {"sd", sd}};
      if (!r.best_tree.empty()) run["best_tree"] = r.best_tree;   // tree controllers, as script code
      // Steps per action or behavior in the run's best evaluation (symbolic heads, supervisors).
      if (!r.action_usage.empty() && r.action_usage.size() == c.choices.size()) {
        nlohmann::ordered_json usage = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < c.choices.size(); ++i) usage[c.choices[i]] = r.action_usage[i];
        run["behavior_usage"] = usage;
      }
      runs.push_back(run);
    }
    controllers[c.name] = {{"architecture", c.architecture}, {"genome_size", c.genome_size},
                           {"runs", runs}};
  }
  return {{"experiment", result.experiment}, {"seed", result.seed}, {"controllers", controllers}};
}

nlohmann::ordered_json study_summary_json(const std::string& study, std::uint64_t seed,
                                          const std::vector<ConditionSummary>& conditions) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ConditionSummary& c : conditions) {
    nlohmann::ordered_json settings = nlohmann::ordered_json::object();
    for (const eval::ConditionSetting& s : c.settings) settings[s.key] = s.value;
    list.push_back({{"name", c.name},
                    {"experiment", c.result.experiment},
                    {"settings", settings},
                    {"controllers", summary_json(c.result)["controllers"]}});
  }
  return {{"study", study}, {"seed", seed}, {"conditions", list}};
}

}  // namespace esc::store
