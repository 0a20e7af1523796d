#include "runtime/store/summary_json.hpp"

#include <cmath>

#include "runtime/eval/success.hpp"
#include "runtime/store/seed_json.hpp"

namespace esc::store {

namespace {

using json = nlohmann::ordered_json;

// Per generation of the run (null where a generation has none stored: written before esc
// counted it): the steps each behavior acted in the best evaluation, their mean over the
// generation's evaluations, and the best evaluation's steps. Null when no generation has any.
json usage_over_generations(const std::vector<std::string>& behaviors, const eval::RunResult& r) {
  bool any = false;
  json best = json::array(), mean = json::array(), total = json::array();
  for (const eval::GenerationStats& g : r.generations) {
    if (g.usage.empty() || g.usage.best.size() != behaviors.size()) {
      best.push_back(nullptr);
      mean.push_back(nullptr);
      total.push_back(nullptr);
      continue;
    }
    any = true;
    best.push_back(g.usage.best);
    mean.push_back(g.usage.mean);
    total.push_back(g.usage.steps_total);
  }
  if (!any) return nullptr;
  return {{"behaviors", behaviors}, {"best_steps", best}, {"mean_steps", mean}, {"steps_total", total}};
}

json number_or_null(std::optional<double> x) { return x ? json(*x) : json(nullptr); }

// Where the run's first genome came from and what became of it here.
json transfer_json(const eval::Transfer& t, const eval::RunResult& r) {
  std::vector<double> best;
  for (const eval::GenerationStats& g : r.generations) best.push_back(g.best);
  json j = {{"experiment", t.experiment}, {"origin_run", t.origin_run + 1}, {"origin_fitness", t.origin_fitness},
            {"fitness_here", number_or_null(t.fitness_here)}, {"change_percent", number_or_null(eval::change_percent(t))}};
  if (!t.evaluate_only) {
    const auto g = eval::regained_at(t, best);
    j["regained_at_generation"] = g ? json(*g) : json(nullptr);
  }
  return j;
}

// How a controller's runs fared against the experiment's success test.
json success_json(const eval::SuccessCount& s) {
  return {{"successes", s.successes}, {"runs", s.runs},
          {"median_evaluations", std::isnan(s.median_evaluations) ? json(nullptr) : json(s.median_evaluations)}};
}

}  // namespace

nlohmann::ordered_json summary_json(const eval::CampaignResult& result) {
  const bool declares_success = !result.success.empty();
  nlohmann::ordered_json controllers = nlohmann::ordered_json::object();
  for (const auto& c : result.controllers) {
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto& r : c.runs) {
      nlohmann::ordered_json best = nlohmann::ordered_json::array();
      nlohmann::ordered_json mean = nlohmann::ordered_json::array();
      std::int64_t saturated = 0;
      for (const auto& g : r.generations) {
        best.push_back(g.best);
        mean.push_back(g.mean);
        saturated += g.saturated;
      }
      nlohmann::ordered_json run = {{"run", r.run + 1}, {"seed", seed_json(r.seed)}, {"best_fitness", r.best_fitness},
                                    {"best", best}, {"mean", mean}};
      // Evaluations whose fitness saturated at +-1e300 (docs/language.md), over the run.
      run["saturated_evaluations"] = saturated;
      if (!r.best_tree.empty()) run["best_tree"] = r.best_tree;   // tree controllers, as script code
      if (!r.stopped.empty()) run["stopped"] = r.stopped;         // the search ended early
      // Steps per action or behavior in the run's best evaluation (symbolic heads, supervisors).
      if (!r.action_usage.empty() && r.action_usage.size() == c.choices.size()) {
        nlohmann::ordered_json usage = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < c.choices.size(); ++i) usage[c.choices[i]] = r.action_usage[i];
        run["behavior_usage"] = usage;
      }
      if (json u = usage_over_generations(c.choices, r); !u.is_null()) run["usage"] = std::move(u);
      if (r.transfer) run["transfer"] = transfer_json(*r.transfer, r);
      if (declares_success) run["success_evaluation"] = r.success_evaluation ? json(*r.success_evaluation) : json(nullptr);
      runs.push_back(run);
    }
    controllers[c.name] = {{"architecture", c.architecture}, {"genome_size", c.genome_size},
                           {"runs", runs}};
    if (declares_success) controllers[c.name]["success"] = success_json(eval::count_successes(c.runs));
  }
  json summary = {{"experiment", result.experiment}, {"seed", seed_json(result.seed)}};
  // A group names its size, its bodies and its roles when several; a robot alone's summary is
  // as it always was.
  if (result.robots > 1) summary["robots"] = result.robots;
  if (!result.bodies.empty()) summary["bodies"] = result.bodies;
  if (result.roles > 1) summary["roles"] = result.roles;
  if (declares_success) summary["success"] = result.success;
  summary["controllers"] = std::move(controllers);
  return summary;
}

nlohmann::ordered_json study_summary_json(const std::string& study, std::uint64_t seed,
                                          const std::vector<ConditionSummary>& conditions) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ConditionSummary& c : conditions) {
    nlohmann::ordered_json settings = nlohmann::ordered_json::object();
    for (const eval::ConditionSetting& s : c.settings) settings[s.key] = s.value;
    json condition = {{"name", c.name}, {"experiment", c.result.experiment}, {"settings", settings}};
    if (!c.result.success.empty()) condition["success"] = c.result.success;
    condition["controllers"] = summary_json(c.result)["controllers"];
    list.push_back(std::move(condition));
  }
  return {{"study", study}, {"seed", seed_json(seed)}, {"conditions", list}};
}

namespace {

bool numbers_only(const nlohmann::ordered_json& array) {
  for (const nlohmann::ordered_json& e : array)
    if (!e.is_number() && !e.is_null()) return false;
  return true;
}

void write_json(std::string& out, const nlohmann::ordered_json& j, std::size_t depth) {
  if (!j.is_structured() || j.empty()) {
    out += j.dump();
    return;
  }
  if (j.is_array() && numbers_only(j)) {
    out += '[';
    for (std::size_t i = 0; i < j.size(); ++i) out += (i == 0 ? "" : ", ") + j[i].dump();
    out += ']';
    return;
  }
  out += j.is_object() ? "{\n" : "[\n";
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out.append(2 * (depth + 1), ' ');
    if (j.is_object()) out += nlohmann::ordered_json(it.key()).dump() + ": ";
    write_json(out, it.value(), depth + 1);
  }
  out += '\n';
  out.append(2 * depth, ' ');
  out += j.is_object() ? '}' : ']';
}

}  // namespace

std::string summary_text(const nlohmann::ordered_json& summary) {
  std::string out;
  write_json(out, summary, 0);
  return out + "\n";
}

}  // namespace esc::store
