#include "cli/end_table.hpp"

#include "app/campaign_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "cli/success_table.hpp"
#include "cli/table_text.hpp"
#include "cli/transfer_table.hpp"
#include "runtime/report/comparisons.hpp"
#include "runtime/report/statistics.hpp"
#include "runtime/report/study_table.hpp"

namespace esc::cli {

namespace {

// Lines are wrapped at this width (sensitivity.esc's supervisors choose among 24 behaviors;
// a sweep may have many conditions).
constexpr std::size_t kWidth = 100;

std::vector<double> best_fitness(const eval::ControllerResult& c) {
  std::vector<double> best;
  for (const auto& r : c.runs) best.push_back(r.best_fitness);
  return best;
}

// Share of control steps each action or behavior acted, over the best evaluations of all
// runs (symbolic heads and supervisors); each line starts with `label(controller)`.
template <class Label>
void print_usage(const eval::CampaignResult& result, bool& header, const Label& label) {
  for (const auto& c : result.controllers) {
    std::vector<std::int64_t> steps(c.choices.size(), 0);
    for (const auto& r : c.runs)
      for (std::size_t i = 0; i < r.action_usage.size() && i < steps.size(); ++i) steps[i] += r.action_usage[i];
    std::int64_t total = 0;
    for (std::int64_t n : steps) total += n;
    if (total == 0) continue;
    if (!header) fmt::print("\nbehavior usage (share of steps in each run's best evaluation)\n");
    header = true;
    std::string line = fmt::format("{:<12} ", label(c));
    const std::size_t indent = line.size();
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string entry = fmt::format("{} {:.0f}%{}", c.choices[i],
                                            100.0 * static_cast<double>(steps[i]) / static_cast<double>(total),
                                            i + 1 < steps.size() ? "," : "");
      if (line.size() > indent && line.size() + 1 + entry.size() > kWidth) {
        fmt::print("{}\n", line);
        line = std::string(indent, ' ');
      }
      line += (line.size() > indent ? " " : "") + entry;
    }
    fmt::print("{}\n", line);
  }
}

// The best tree of each run of the tree controllers, as script code.
template <class Label>
void print_trees(const eval::CampaignResult& result, const Label& label) {
  for (const auto& c : result.controllers)
    for (const auto& r : c.runs)
      if (!r.best_tree.empty())
        fmt::print("{:<12} run {} best tree (fitness {:.{}f}): {}\n", label(c), r.run + 1, r.best_fitness,
                   fitness_decimals(r.best_fitness), r.best_tree);
}

// Each run whose optimizer ended the search early, and why; the runs that ended at their first
// success, counted in one line per controller (a maze study's would fill the screen).
template <class Label>
void print_stops(const eval::CampaignResult& result, const Label& label) {
  for (const auto& c : result.controllers) {
    std::size_t at_success = 0;
    for (const auto& r : c.runs)
      if (r.stopped == eval::kStopAtSuccess)
        ++at_success;
      else if (!r.stopped.empty())
        fmt::print("{:<12} run {} stopped its search after generation {} ({}): best fitness {:.{}f}\n", label(c),
                   r.run + 1, r.generations.size() - 1, r.stopped, r.best_fitness, fitness_decimals(r.best_fitness));
    if (at_success > 0)
      fmt::print("{:<12} {} of {} runs stopped at their first success ({})\n", label(c), at_success, c.runs.size(),
                 eval::kStopAtSuccess);
  }
}

// Decimals of a summary of fitness values: as many as its largest value or spread needs.
int summary_decimals(const report::Summary& s) {
  return fitness_decimals(std::max({std::abs(s.min), std::abs(s.max), s.sd}));
}

bool has_trees(const eval::ExperimentSpec& spec) {
  return std::any_of(spec.controllers.begin(), spec.controllers.end(), [](const auto& c) { return c.is_tree(); });
}

// The comparisons of one Holm family, each row labelled "A vs B" by `label`, then `family`:
// what the family holds.
void print_comparisons(const std::vector<report::Comparison>& rows, const PairLabel& label, const std::string& family) {
  if (rows.empty()) return;
  std::size_t width = 26;
  for (const report::Comparison& c : rows) width = std::max(width, label(c.a, c.b).size());
  fmt::print("\n{:<{}} {:>9} {:>7} {:>10} {:>10}  {:>7} {:>10} {:>10}  {:>5}  {:>7} {:>10} {:>10}\n",
             "pairwise (two-sided)", width, "Welch t", "df", "p", "p Holm", "M-W U", "p", "p Holm", "A12", "sd a/b",
             "B-F p", "p Holm");
  for (const report::Comparison& c : rows)
    fmt::print("{:<{}} {:>9} {:>7} {:>10} {:>10}  {:>7} {:>10} {:>10}  {:>5}  {:>7} {:>10} {:>10}\n", label(c.a, c.b),
               width, number_or_na(c.welch.statistic, 3), number_or_na(c.welch.df, 1), p_text(c.welch.p_value),
               p_text(c.welch_p_holm), number_or_na(c.mann_whitney.statistic, 1), p_text(c.mann_whitney.p_value),
               p_text(c.mann_whitney_p_holm), number_or_na(c.a12, 2), number_or_na(c.sd_ratio, 2),
               p_text(c.spread.p_value), p_text(c.spread_p_holm));
  fmt::print("Holm: p adjusted over the {} comparison{} shown{}, for each test. Mann-Whitney p exact when a sample has "
             "at most 8 runs and no ties. A12: chance the first beats the second. B-F: Brown-Forsythe test of equal "
             "spread (Levene's about the medians).\n",
             rows.size(), rows.size() == 1 ? "" : "s", family);
}

// The study's cells and its one family of comparisons (report/study_table.hpp), as the
// report shows them.
report::StudyTable study_table_of(const std::vector<ConditionResult>& conditions) {
  std::vector<report::ConditionSamples> samples;
  for (const ConditionResult& c : conditions) {
    report::ConditionSamples s{c.name, {}};
    for (const auto& r : c.result.controllers) {
      s.controllers.emplace_back(r.name, best_fitness(r));
      if (!c.result.success.empty()) s.success.push_back(report::success_sample(r.runs));
    }
    samples.push_back(std::move(s));
  }
  return report::study_table(samples);
}

}  // namespace

void print_table(const eval::ExperimentSpec& spec, const eval::CampaignResult& result) {
  // A group says its size and roles: the genes below are every role's.
  const std::string group =
      spec.robots == 1 ? std::string()
                       : fmt::format(", {} robots{}", spec.robots,
                                     spec.roles > 1 ? fmt::format(" in {} roles", spec.roles) : std::string());
  fmt::print("\n{}: {} run{} x {}, {} epoch{} x {} steps{}, seed {}\n", spec.name, spec.runs,
             spec.runs == 1 ? "" : "s", app::generations_text(spec), spec.epochs, spec.epochs == 1 ? "" : "s",
             spec.steps, group, spec.seed);
  // As wide as the longest architecture: a controller per body's names each body's network.
  std::size_t wide = 14;
  for (const auto& c : result.controllers) wide = std::max(wide, c.architecture.size());
  fmt::print("{:<12} {:<{}} {:>6}  {:>22}  {:>10}  {:>10}\n", "controller", "architecture", wide, "genes",
             "best fitness mean ± sd", "median", "best run");
  std::vector<std::vector<double>> finals;
  for (const auto& c : result.controllers) {
    std::vector<double> best = best_fitness(c);
    const report::Summary s = report::summarise(best);
    const int d = summary_decimals(s);
    fmt::print("{:<12} {:<{}} {:>6}  {:>12.{}f} ± {:<7.{}f}  {:>10.{}f}  {:>10.{}f}\n", c.name, c.architecture, wide,
               c.genome_size, s.mean, d, s.sd, d, s.median, d, s.max, d);
    finals.push_back(std::move(best));
  }
  print_transfers(result);
  print_success(result);
  const auto name = [](const eval::ControllerResult& c) { return c.name; };
  bool header = false;
  print_usage(result, header, name);
  if (has_trees(spec)) {
    fmt::print("\n");
    print_trees(result, name);
  }
  print_stops(result, name);
  const auto& cs = result.controllers;
  const auto pairs = report::all_pairs(finals.size());
  const PairLabel label = [&](std::size_t a, std::size_t b) { return fmt::format("{} vs {}", cs[a].name, cs[b].name); };
  print_comparisons(report::compare(finals, pairs), label, "");
  if (result.success.empty()) return;
  std::vector<report::SuccessSample> success;
  for (const auto& c : cs) success.push_back(report::success_sample(c.runs));
  print_success_comparisons(report::compare_success(success, pairs), label, "");
}

void print_study_table(const std::string& study, const std::vector<ConditionResult>& conditions) {
  const report::StudyTable t = study_table_of(conditions);
  const std::vector<std::string>& controllers = t.controllers;
  const eval::ExperimentSpec& first = *conditions.front().spec;
  fmt::print("\nstudy {}: {} condition{}, seed {}; best fitness of each run, mean ± sd (median)\n", study,
             conditions.size(), conditions.size() == 1 ? "" : "s", first.seed);
  std::size_t name_width = 12;
  for (const ConditionResult& c : conditions) name_width = std::max(name_width, c.name.size());
  constexpr std::size_t kCell = 24;
  const std::size_t per_block = std::max<std::size_t>(1, (kWidth - name_width) / (kCell + 2));
  for (std::size_t from = 0; from < controllers.size(); from += per_block) {
    const std::size_t to = std::min(controllers.size(), from + per_block);
    std::string head = fmt::format("{:<{}}", "condition", name_width);
    for (std::size_t j = from; j < to; ++j) head += fmt::format("  {:>{}}", controllers[j], kCell);
    fmt::print("{}{}\n", from == 0 ? "" : "\n", head);
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      std::string line = fmt::format("{:<{}}", conditions[i].name, name_width);
      for (std::size_t j = from; j < to; ++j) {
        const report::StudyCell* s = t.cell(i, j);
        const report::Summary m = s != nullptr ? report::summarise(s->best) : report::Summary{};
        const int d = summary_decimals(m);
        line += fmt::format("  {:>{}}", s == nullptr || s->best.empty() ? "-"
                                            : fmt::format("{:.{}f} ± {:.{}f} ({:.{}f})", m.mean, d, m.sd, d, m.median, d),
                            kCell);
      }
      fmt::print("{}\n", line);
    }
  }
  for (const ConditionResult& c : conditions)
    if (c.spec->runs != first.runs || c.spec->max_generations() != first.max_generations() ||
        c.spec->epochs != first.epochs || c.spec->steps != first.steps) {
      fmt::print("(conditions differ in runs, generations, epochs or steps: see each one's settings.json)\n");
      break;
    }
  fmt::print("{} run{} x {}, {} epoch{} x {} steps{}\n", first.runs, first.runs == 1 ? "" : "s",
             app::generations_text(first), first.epochs, first.epochs == 1 ? "" : "s", first.steps,
             conditions.size() > 1 ? " (the first condition)" : "");
  print_study_success(conditions, controllers);

  bool header = false;
  for (const ConditionResult& c : conditions)
    print_usage(c.result, header, [&](const eval::ControllerResult& r) { return fmt::format("{} {}", r.name, c.name); });
  bool trees = false;
  for (const ConditionResult& c : conditions) {
    if (!has_trees(*c.spec)) continue;
    if (!trees) fmt::print("\n");
    trees = true;
    print_trees(c.result, [&](const eval::ControllerResult& r) { return fmt::format("{} {}", r.name, c.name); });
  }
  for (const ConditionResult& c : conditions)
    print_stops(c.result, [&](const eval::ControllerResult& r) { return fmt::format("{} {}", r.name, c.name); });

  const PairLabel label = [&](std::size_t a, std::size_t b) { return t.label(a, b); };
  const std::string family = fmt::format(" ({})", report::kStudyFamily);
  print_comparisons(t.comparisons, label, family);
  print_success_comparisons(t.success_comparisons, label, family);
}

}  // namespace esc::cli
