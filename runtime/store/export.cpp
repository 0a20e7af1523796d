#include "runtime/store/export.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "runtime/store/seed_json.hpp"

namespace esc::store {

namespace {

using json = nlohmann::ordered_json;

json generations_json(const std::vector<eval::GenerationStats>& gens) {
  json a = json::array();
  for (const auto& g : gens) {
    a.push_back({{"generation", g.generation}, {"best", g.best}, {"mean", g.mean}, {"sd", g.sd},
                 {"evaluations", g.evaluations}, {"steps", g.steps}, {"seconds", g.seconds},
                 {"saturated", g.saturated}});
    if (!g.usage.empty())
      a.back()["usage"] = {{"best_steps", g.usage.best}, {"mean_steps", g.usage.mean},
                           {"steps_total", g.usage.steps_total}};
    if (!g.metrics.empty()) {
      json m = json::object();
      for (const evo::Metric& x : g.metrics) m[x.name] = std::isnan(x.value) ? json(nullptr) : json(x.value);
      a.back()["metrics"] = std::move(m);
    }
  }
  return a;
}

json run_json(const StoredController& c, const eval::RunResult& r) {
  json usage = json::object();
  for (std::size_t i = 0; i < r.action_usage.size(); ++i)
    usage[i < c.actions.size() ? c.actions[i] : fmt::format("action{}", i)] = r.action_usage[i];
  json j = {{"run", r.run + 1}, {"seed", seed_json(r.seed)}, {"status", "finished"}, {"best_fitness", r.best_fitness},
            {"best_generation", r.best_generation}, {"best_index", r.best_index}, {"best_genome", r.best_genome}};
  if (!r.best_tree.empty()) j["best_tree"] = r.best_tree;
  if (!r.stopped.empty()) j["stopped"] = r.stopped;
  j["behavior_usage"] = usage;
  if (r.transfer)
    j["transfer"] = {{"experiment", r.transfer->experiment}, {"origin_run", r.transfer->origin_run + 1},
                     {"origin_fitness", r.transfer->origin_fitness}, {"evaluate_only", r.transfer->evaluate_only},
                     {"fitness_here", r.transfer->fitness_here ? json(*r.transfer->fitness_here) : json(nullptr)}};
  j["generations"] = generations_json(r.generations);
  return j;
}

// What the optimizer kept beside the best: its layout, then a row per member and generation.
json members_json(const StoredMembers& m) {
  const eval::MemberLayout& l = m.layout;
  json objectives = json::array(), descriptors = json::array(), rows = json::array();
  for (std::size_t i = 0; i < l.objectives.size(); ++i)
    objectives.push_back({{"name", l.objectives[i]}, {"minimize", static_cast<bool>(l.minimized[i])}});
  for (std::size_t i = 0; i < l.descriptors.size(); ++i)
    descriptors.push_back({{"name", l.descriptors[i]}, {"lower", l.descriptor_ranges[i].lower},
                           {"upper", l.descriptor_ranges[i].upper}});
  for (const StoredMember& r : m.rows)
    rows.push_back({{"run", r.run + 1}, {"generation", r.generation}, {"cell", r.cell}, {"objectives", r.objectives},
                    {"descriptors", r.descriptors}});
  json j = {{"kind", member_kind_name(l.kind)}, {"objectives", objectives},
            {"descriptors", descriptors}};
  if (!l.bins.empty()) j["bins"] = l.bins;
  if (!l.centroids.empty()) j["centroids"] = l.centroids;
  j["rows"] = rows;
  return j;
}

json run_json(const eval::RunState& s) {
  json j = {{"run", s.run + 1}, {"seed", seed_json(s.seed)}, {"status", "running"}};
  if (s.has_best) {
    j["best_fitness"] = s.best_fitness;
    j["best_genome"] = s.best_genome;
  }
  j["generations"] = generations_json(s.generations);
  return j;
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

json export_json(const std::vector<StoredDirectory>& directories) {
  json exps = json::array();
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments) {
      json sources = json::array();
      for (const auto& s : e.sources) sources.push_back({{"name", s.name.generic_string()}, {"text", s.text}});
      json controllers = json::object();
      for (const StoredController& c : e.controllers) {
        json runs = json::array();
        for (const auto& r : c.finished) runs.push_back(run_json(c, r));
        for (const auto& s : c.in_progress) runs.push_back(run_json(s));
        controllers[c.name] = {{"architecture", c.architecture}, {"genome_size", c.genome_size}, {"head", c.head},
                               {"algorithm", c.algorithm}, {"actions", c.actions}, {"runs", runs}};
        if (c.members) controllers[c.name]["members"] = members_json(*c.members);
      }
      json x = {{"name", e.name}, {"directory", d.path.generic_string()}};
      // A group names its size, roles and bodies (its `robots`, `roles` and `bodies` settings,
      // each resolved only for a group, several roles, several bodies); a robot alone's export
      // is as it always was.
      for (const char* key : {"robots", "roles"})
        if (const auto it = e.settings.find(key); it != e.settings.end()) x[key] = std::atoi(it->second.c_str());
      if (const auto it = e.settings.find("bodies"); it != e.settings.end()) x["bodies"] = it->second;
      if (e.condition) {
        json settings = json::object();
        for (const eval::ConditionSetting& st : e.condition->settings) settings[st.key] = st.value;
        x.update({{"study", e.condition->study}, {"condition", e.condition->name}, {"condition_settings", settings}});
      }
      x.update({{"seed", seed_json(e.seed)}, {"content_hash", e.content_hash}, {"status", e.status}, {"created", e.created},
                {"software_version", e.software_version}, {"script", e.script.generic_string()},
                {"overrides", e.overrides}, {"settings", json(e.settings)}, {"arena", e.arena}, {"runs", e.runs},
                {"generations", e.generations}, {"epochs", e.epochs}, {"steps", e.steps}, {"sources", sources},
                {"controllers", controllers}});
      exps.push_back(std::move(x));
    }
  return {{"format", "esc results"}, {"schema_version", kSchemaVersion}, {"experiments", exps}};
}

void for_each_run(const std::vector<StoredDirectory>& directories,
                  const std::function<void(const StoredExperiment&, const std::string&, const StoredController&, int,
                                           const std::vector<eval::GenerationStats>&)>& f) {
  static const std::string kNone;
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments) {
      const std::string& condition = e.condition ? e.condition->name : kNone;
      for (const StoredController& c : e.controllers) {
        for (const eval::RunResult& r : c.finished) f(e, condition, c, r.run, r.generations);
        for (const eval::RunState& s : c.in_progress) f(e, condition, c, s.run, s.generations);
      }
    }
}

std::string export_csv(const std::vector<StoredDirectory>& directories) {
  std::string out =
      "experiment,controller,run,run_seed,status,generation,best,mean,sd,evaluations,steps,seconds,condition,study,"
      "directory,algorithm\n";
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments) {
      // A grid sweep's point is named with commas (`time_constant=50ms,mu=10`).
      const std::string condition = csv_field(e.condition ? e.condition->name : e.name);
      const std::string study = e.condition ? e.condition->study : "";
      const auto rows = [&](const StoredController& c, int run, std::uint64_t seed, const char* status,
                            const std::vector<eval::GenerationStats>& gens) {
        for (const auto& g : gens)
          out += fmt::format("{},{},{},{},{},{},{:.17g},{:.17g},{:.17g},{},{},{:.3f},{},{},{},{}\n", e.name, c.name,
                             run + 1, seed, status, g.generation, g.best, g.mean, g.sd, g.evaluations, g.steps,
                             g.seconds, condition, study, csv_field(d.path.generic_string()), c.algorithm);
      };
      for (const StoredController& c : e.controllers) {
        for (const auto& r : c.finished) rows(c, r.run, r.seed, "finished", r.generations);
        for (const auto& s : c.in_progress) rows(c, s.run, s.seed, "running", s.generations);
      }
    }
  return out;
}

}  // namespace esc::store
