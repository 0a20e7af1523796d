#include "runtime/report/html_report.hpp"

#include <cmath>
#include <set>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include "runtime/report/comparisons.hpp"
#include "runtime/report/generalization.hpp"
#include "runtime/report/markup.hpp"
#include "runtime/report/statistics.hpp"
#include "runtime/report/stored_study.hpp"
#include "runtime/report/study_table.hpp"
#include "runtime/report/success_comparisons.hpp"
#include "runtime/report/success_table.hpp"
#include "runtime/report/usage_figure.hpp"
#include "runtime/eval/success.hpp"
#include "runtime/sim/ir_sensor.hpp"
#include "runtime/store/seed_json.hpp"

extern const unsigned char esc_embed_chartjs[];
extern const std::size_t esc_embed_chartjs_size;
extern const unsigned char esc_embed_report_js[];
extern const std::size_t esc_embed_report_js_size;
extern const unsigned char esc_embed_report_css[];
extern const std::size_t esc_embed_report_css_size;

namespace esc::report {

namespace {

using json = nlohmann::ordered_json;

std::string_view embedded(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Rounds to `digits` decimals, so the page carries no meaningless digits.
double round_to(double x, int digits) {
  const double f = std::pow(10.0, digits);
  return std::round(x * f) / f;
}

// A number or null (JSON has no NaN).
json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json replay_json(const store::StoredController& c, const ReportOptions& o) {
  if (!c.replay) return nullptr;
  const auto& steps = c.replay->steps;
  // Whole epochs while they fit, at least the first epoch's beginning.
  const std::size_t keep = eval::trace_rows_kept(steps, o.max_replay_steps);
  const auto readings = [](std::span<const double> values) {
    json a = json::array();
    for (double v : values) a.push_back(round_to(v, 3));
    return a;
  };
  // A robot with rangefinders or goal radars (the maze navigator) adds their readings to
  // each row; the paper's robots have neither, and their rows stay as they were.
  const bool navigation = !steps.empty() && (steps.front().range_count > 0 || steps.front().radar_count > 0);
  // A group's rows are a row per robot per step, each ending with its robot (from 0).
  const bool group = !steps.empty() && steps.front().grouped;
  json rows = json::array();
  for (std::size_t i = 0; i < keep; ++i) {
    const eval::TraceStep& t = steps[i];
    json row = {t.epoch, t.step, round_to(t.pose.x_m * 1000.0, 1), round_to(t.pose.y_m * 1000.0, 1),
                round_to(t.pose.heading_rad, 3), readings(t.ir), round_to(t.left_command, 3),
                round_to(t.right_command, 3), t.action, round_to(t.fitness, 4), t.collided ? 1 : 0,
                round_to(t.energy, 3), readings(t.light)};
    if (navigation) {
      row.push_back(readings(std::span(t.range).first(t.range_count)));
      row.push_back(readings(std::span(t.radar).first(t.radar_count)));
    }
    if (group) row.push_back(t.robot);
    rows.push_back(std::move(row));
  }
  json columns = {"epoch", "step", "x_mm", "y_mm", "heading", "ir", "left", "right", "action", "fitness", "collided",
                  "energy", "light"};
  if (navigation) {
    columns.push_back("range");
    columns.push_back("radar");
  }
  if (group) columns.push_back("robot");
  int epochs = steps.empty() ? 0 : steps.back().epoch + 1;
  // Where the zones were in each epoch (random zones move at every epoch start), in mm.
  json epoch_zones = json::array();
  for (const eval::TraceStep& t : steps) {
    if (static_cast<std::size_t>(t.epoch) < epoch_zones.size()) continue;
    while (epoch_zones.size() < static_cast<std::size_t>(t.epoch)) epoch_zones.push_back(json::array());
    json zones = json::array();
    for (std::size_t z = 0; z < t.zone_count; ++z)
      zones.push_back({round_to(t.zones[z].x * 1000.0, 1), round_to(t.zones[z].y * 1000.0, 1)});
    epoch_zones.push_back(std::move(zones));
  }
  const std::size_t robots = eval::trace_robots(steps);
  json replay = {{"run", c.replay->run + 1},
          {"seed", store::seed_json(c.replay->seed)},
          {"fitness", c.replay->fitness},
          {"total_steps", steps.size() / robots},
          {"total_epochs", epochs},
          {"columns", columns},
          {"epoch_zones", epoch_zones},
          {"rows", rows}};
  if (group) replay["robots"] = robots;
  return replay;
}

json summary_json(const Summary& s) {
  return {{"n", s.n}, {"mean", number(s.mean)}, {"sd", number(s.sd)}, {"median", number(s.median)},
          {"best", number(s.max)}, {"worst", number(s.min)}};
}

json pair_json(const std::string& a, const std::string& b, const Comparison& c) {
  return {{"a", a}, {"b", b},
          {"welch_t", number(c.welch.statistic)}, {"welch_df", number(c.welch.df)},
          {"welch_p", number(c.welch.p_value)}, {"welch_p_holm", number(c.welch_p_holm)},
          {"mwu_u", number(c.mann_whitney.statistic)}, {"mwu_p", number(c.mann_whitney.p_value)},
          {"mwu_p_holm", number(c.mann_whitney_p_holm)}, {"mwu_exact", c.mann_whitney.exact},
          {"a12", number(c.a12)}, {"sd_ratio", number(c.sd_ratio)}, {"bf_w", number(c.spread.statistic)},
          {"bf_p", number(c.spread.p_value)}, {"bf_p_holm", number(c.spread_p_holm)}};
}

json success_count_json(const eval::SuccessCount& s) {
  return {{"successes", s.successes}, {"runs", s.runs}, {"median_evaluations", number(s.median_evaluations)}};
}

json success_pair_json(const SuccessComparison& c) {
  return {{"successes_a", c.successes_a}, {"runs_a", c.runs_a}, {"successes_b", c.successes_b}, {"runs_b", c.runs_b},
          {"fisher_p", number(c.fisher.p_value)}, {"fisher_p_holm", number(c.fisher_p_holm)},
          // JSON has no infinity: every run of the second failed and one of the first succeeded.
          {"odds_ratio", std::isinf(c.fisher.odds_ratio) ? json("inf") : number(c.fisher.odds_ratio)},
          {"censored_u", number(c.censored.statistic)},
          {"censored_p", number(c.censored.p_value)}, {"censored_p_holm", number(c.censored_p_holm)},
          {"censored_at", number(c.censored_at)}};
}

// The experiment's success test, if it declares one: per controller its runs' successes,
// and Fisher's and the censored Mann-Whitney test of every pair (one family each).
json experiment_success_json(const store::StoredExperiment& e) {
  const auto test = e.settings.find("success");
  if (test == e.settings.end()) return nullptr;
  json controllers = json::array();
  for (const store::StoredController& c : e.controllers) {
    json row = {{"controller", c.name}};
    row.update(success_count_json(eval::count_successes(c.finished)));
    controllers.push_back(std::move(row));
  }
  json pairs = json::array();
  for (const SuccessComparison& c : experiment_success(e)) {
    json p = {{"a", e.controllers[c.a].name}, {"b", e.controllers[c.b].name}};
    p.update(success_pair_json(c));
    pairs.push_back(std::move(p));
  }
  return {{"test", test->second}, {"controllers", controllers}, {"pairs", pairs}};
}

json figures_json(const std::vector<NamedFigure>& figures) {
  json list = json::array();
  for (const NamedFigure& f : figures) list.push_back({{"file", f.file}, {"title", f.title}, {"svg", f.svg}});
  return list;
}

// One per-generation series of the runs (each generation's best or mean fitness): per
// generation, the mean over the runs that reached it and its sample sd (0 for one run).
json run_curves(const std::vector<eval::RunResult>& runs, double eval::GenerationStats::*series) {
  std::size_t length = 0;
  for (const eval::RunResult& r : runs) length = std::max(length, r.generations.size());
  json mean = json::array(), sd = json::array();
  for (std::size_t g = 0; g < length; ++g) {
    std::vector<double> values;
    for (const eval::RunResult& r : runs)
      if (g < r.generations.size()) values.push_back(r.generations[g].*series);
    const Summary s = summarise(values);
    mean.push_back(number(s.mean));
    sd.push_back(number(s.sd));
  }
  return {{"mean", mean}, {"sd", sd}};
}

// The paper's Figure 2 for one run: per generation, the calls of each behavior per 10,000
// steps, in the generation's best evaluation ("best") and on average over its evaluations
// ("mean"); null for a generation stored without usage.
json usage_curves(const eval::RunResult& r, std::size_t choices) {
  json best = json::array(), mean = json::array();
  for (const eval::GenerationStats& g : r.generations) {
    const eval::GenerationUsage& u = g.usage;
    const double steps_per_evaluation = g.evaluations > 0 ? static_cast<double>(g.steps) / static_cast<double>(g.evaluations) : 0.0;
    if (u.best.size() != choices || u.steps_total <= 0 || steps_per_evaluation <= 0.0) {
      best.push_back(nullptr);
      mean.push_back(nullptr);
      continue;
    }
    json b = json::array(), m = json::array();
    for (std::size_t i = 0; i < choices; ++i) {
      b.push_back(round_to(1e4 * static_cast<double>(u.best[i]) / static_cast<double>(u.steps_total), 2));
      m.push_back(round_to(1e4 * u.mean[i] / steps_per_evaluation, 2));
    }
    best.push_back(std::move(b));
    mean.push_back(std::move(m));
  }
  return {{"run", r.run + 1}, {"best", best}, {"mean", mean}};
}

// The usage chart's panels and lines, as the SVG figure draws them (usage_figure.hpp).
json usage_panels_json(const store::StoredController& c) {
  json out = json::array();
  for (const UsagePanel& p : usage_panels(c)) {
    json lines = json::array();
    for (const UsageLine& l : p.lines) lines.push_back({{"label", l.label}, {"indices", l.indices}});
    out.push_back({{"title", p.title}, {"by_library", p.by_library}, {"lines", lines}});
  }
  return out;
}

json transfers_json(const std::vector<eval::RunResult>& runs) {
  const auto s = summarise_transfers(runs);
  if (!s) return nullptr;
  const auto opt = [](const auto& x) { return x ? json(*x) : json(nullptr); };
  json per_run = json::array();
  for (const RunTransfer& t : s->runs)
    per_run.push_back({{"run", t.run + 1}, {"origin_run", t.origin_run + 1}, {"origin_fitness", t.origin_fitness},
                       {"fitness_here", opt(t.fitness_here)}, {"change_percent", opt(t.change_percent)},
                       {"regained_at", opt(t.regained_at)}, {"best_here", opt(t.best_here)},
                       {"loss_regained", opt(t.loss_regained)}});
  return {{"origin", s->origin},
          {"evaluate_only", s->evaluate_only},
          {"origin_mean", number(s->origin_mean)},
          {"here_mean", number(s->here_mean)},
          {"change_mean", number(s->change_mean)},
          {"regained", s->regained},
          {"regained_median", number(s->regained_median)},
          {"best_here_mean", number(s->best_here_mean)},
          {"loss_regained_pooled", number(s->loss_regained_pooled)},
          {"runs", per_run}};
}

json experiment_json(const store::StoredExperiment& e, const ReportOptions& o) {
  json controllers = json::array();
  json summary = json::array();
  for (const store::StoredController& c : e.controllers) {
    json runs = json::array();
    std::vector<double> final_best;
    json usage = json::array();
    json usage_generations = json::array();
    for (const auto& r : c.finished) {
      if (!c.actions.empty()) usage_generations.push_back(usage_curves(r, c.actions.size()));
      runs.push_back({{"run", r.run + 1}, {"best_fitness", r.best_fitness}});
      if (r.success_evaluation) runs.back()["success_evaluation"] = *r.success_evaluation;
      if (!r.best_tree.empty()) runs.back()["best_tree"] = r.best_tree;   // tree controllers
      final_best.push_back(r.best_fitness);
      if (!r.action_usage.empty()) usage.push_back(r.action_usage);
    }
    // The fitness charts' curves, over the runs per generation: a study of 160 runs x 1000
    // generations embedded every run's series (3.9 MB of the hard maze study's report).
    const json curves = {{"best", run_curves(c.finished, &eval::GenerationStats::best)},
                         {"mean", run_curves(c.finished, &eval::GenerationStats::mean)}};
    json row = {{"controller", c.name}};
    row.update(summary_json(summarise(final_best)));
    summary.push_back(std::move(row));
    controllers.push_back({{"name", c.name}, {"architecture", c.architecture}, {"genome_size", c.genome_size},
                           {"head", c.head}, {"actions", c.actions}, {"runs", runs}, {"curves", curves},
                           {"unfinished_runs", c.in_progress.size()}, {"usage", usage},
                           {"usage_panels", usage_panels_json(c)}, {"usage_generations", usage_generations},
                           {"transfers", transfers_json(c.finished)}, {"replay", replay_json(c, o)}});
  }
  json pairs = json::array();
  for (const Comparison& c : experiment_comparisons(e))
    pairs.push_back(pair_json(e.controllers[c.a].name, e.controllers[c.b].name, c));
  json j = {{"name", e.name},
            {"seed", store::seed_json(e.seed)},
            {"status", e.status},
            {"created", e.created},
            {"software_version", e.software_version},
            {"content_hash", e.content_hash},
            {"script", e.script.generic_string()},
            {"settings", json(e.settings)},
            {"runs", e.runs},
            {"generations", e.generations},
            {"epochs", e.epochs},
            {"steps", e.steps},
            {"arena", e.arena},
            {"robot_radius_mm", e.robot_radius_m * 1000.0},
            {"ir_mount_deg", sim::kKheperaIrMountDeg},
            {"ir_facing_deg", sim::kKheperaIrFacingDeg},
            {"controllers", controllers},
            {"stats", {{"summary", summary}, {"pairs", pairs}}}};
  if (json success = experiment_success_json(e); !success.is_null()) j["success"] = std::move(success);
  if (e.condition) {
    json settings = json::object();
    for (const eval::ConditionSetting& st : e.condition->settings) settings[st.key] = st.value;
    j["study"] = e.condition->study;
    j["condition"] = e.condition->name;
    j["condition_settings"] = settings;
  }
  return j;
}

// A study's table and comparisons; `conditions` in the study's order.
json study_json(const std::vector<const store::StoredExperiment*>& conditions) {
  std::vector<ConditionSamples> samples;
  for (const auto* e : conditions) samples.push_back(condition_samples(*e));
  const StudyTable t = study_table(samples);
  json cells = json::array();
  for (const StudyCell& c : t.cells) {
    json cell = {{"condition", t.conditions[c.condition]}, {"controller", t.controllers[c.controller]}};
    cell.update(summary_json(summarise(c.best)));
    if (c.success) cell["success"] = success_count_json(eval::count_successes(c.success->evaluations));
    cells.push_back(std::move(cell));
  }
  json pairs = json::array();
  for (const Comparison& c : t.comparisons) {
    json p = pair_json(t.controllers[t.cells[c.a].controller], t.controllers[t.cells[c.b].controller], c);
    p["label"] = t.label(c);
    pairs.push_back(std::move(p));
  }
  json list = json::array();
  for (const auto* e : conditions) {
    json settings = json::object();
    for (const eval::ConditionSetting& st : e->condition->settings) settings[st.key] = st.value;
    list.push_back({{"name", e->condition->name}, {"experiment", e->name}, {"status", e->status},
                    {"settings", settings}});
    if (const auto test = e->settings.find("success"); test != e->settings.end()) list.back()["success"] = test->second;
  }
  const store::StoredCondition& first = *conditions.front()->condition;
  json j = {{"name", first.study},
            {"seed", store::seed_json(first.study_seed)},
            {"conditions", list},
            {"controllers", t.controllers},
            {"cells", cells},
            {"pairs", pairs},
            {"family", kStudyFamily}};
  if (!t.success_comparisons.empty()) {
    json success = json::array();
    for (const SuccessComparison& c : t.success_comparisons) {
      json p = success_pair_json(c);
      p["label"] = t.label(c.a, c.b);
      success.push_back(std::move(p));
    }
    j["success_pairs"] = std::move(success);
  }
  return j;
}

// `stem`, or `stem-2`, `stem-3`, ... when taken (reports over several directories).
std::string unique(std::set<std::string>& taken, const std::string& stem) {
  std::string s = stem;
  for (int i = 2; !taken.insert(s).second; ++i) s = fmt::format("{}-{}", stem, i);
  return s;
}

// JSON inside <script>: "</" would end the element early.
std::string script_safe(std::string s) {
  for (std::size_t i = 0; (i = s.find("</", i)) != std::string::npos; i += 3) s.replace(i, 2, "<\\/");
  return s;
}

}  // namespace

Report make_report(const std::vector<store::StoredDirectory>& directories, const ReportOptions& options) {
  Report r;
  json experiments = json::array();
  json studies = json::array();
  std::set<std::string> stems;
  std::string title = "esc report";
  for (const store::StoredDirectory& d : directories) {
    // The study of this directory, if it is one: its conditions in order.
    const std::vector<const store::StoredExperiment*> conditions = conditions_in_order(d);
    if (!conditions.empty()) {
      const std::string& study = conditions.front()->condition->study;
      std::vector<NamedFigure> figures = study_figures(conditions, unique(stems, study));
      json j = study_json(conditions);
      j["directory"] = d.path.generic_string();
      j["figures"] = figures_json(figures);
      studies.push_back(std::move(j));
      r.figures.insert(r.figures.end(), figures.begin(), figures.end());
    }
    for (const store::StoredExperiment& e : d.experiments) {
      const std::string stem = e.condition ? e.condition->study + "-" + e.condition->directory : e.name;
      std::vector<NamedFigure> figures = experiment_figures(e, unique(stems, stem));
      json j = experiment_json(e, options);
      j["directory"] = d.path.generic_string();
      j["figures"] = figures_json(figures);
      experiments.push_back(std::move(j));
      r.figures.insert(r.figures.end(), figures.begin(), figures.end());
    }
    if (title == "esc report" && !d.experiments.empty())
      title += ": " + (conditions.empty() ? d.experiments.front().name : conditions.front()->condition->study);
  }
  r.data = {{"studies", studies}, {"experiments", experiments}};

  std::string& page = r.html;
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += fmt::format("<title>{}</title>\n<style>\n", escape_markup(title));
  page += embedded(esc_embed_report_css, esc_embed_report_css_size);
  page += "</style>\n</head>\n<body>\n";
  // Installed first, so that an error anywhere below, Chart.js included, shows on the page.
  page += "<script>window.escErrors=[];window.addEventListener('error',function(e){"
          "window.escErrors.push(String(e.message));var d=document.getElementById('esc-errors');"
          "if(d){var p=document.createElement('p');p.className='esc-error';p.textContent='Script error: '+e.message;"
          "d.appendChild(p);}document.title=document.title.replace(' (ready)','')+' (script error)';});</script>\n";
  page += "<div id=\"esc-errors\"></div>\n<main id=\"esc-report\"><p>Loading the report&hellip;</p></main>\n";
  page += "<script id=\"esc-data\" type=\"application/json\">";
  page += script_safe(r.data.dump());
  page += "</script>\n<script>\n";
  page += embedded(esc_embed_chartjs, esc_embed_chartjs_size);
  page += "\n</script>\n<script>\n";
  page += embedded(esc_embed_report_js, esc_embed_report_js_size);
  page += "\n</script>\n</body>\n</html>\n";
  return r;
}

json report_data(const std::vector<store::StoredExperiment>& experiments, const ReportOptions& options) {
  return make_report({{{}, experiments}}, options).data;
}

std::string html_report(const std::vector<store::StoredExperiment>& experiments, const ReportOptions& options) {
  return make_report({{{}, experiments}}, options).html;
}

}  // namespace esc::report
