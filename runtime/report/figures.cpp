#include "runtime/report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "runtime/report/member_figures.hpp"
#include "runtime/report/statistics.hpp"
#include "runtime/report/svg_plot.hpp"
#include "runtime/report/network_figure.hpp"
#include "runtime/report/usage_figure.hpp"

namespace esc::report {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Bands of ± one sd stay readable up to this many controllers.
constexpr std::size_t kMostBands = 6;

std::vector<double> best_fitness(const store::StoredController& c) {
  std::vector<double> v;
  for (const auto& r : c.finished) v.push_back(r.best_fitness);
  return v;
}

// Over the finished runs, generation by generation: the maximum and the mean (with sd) of
// each generation's best, and the mean of each run's best so far (a run its optimizer
// stopped early keeps its best so far after its last generation).
struct Curves {
  std::vector<double> x, max, mean, lo, hi, so_far;
};

Curves curves(const store::StoredController& c) {
  Curves k;
  std::size_t length = 0;
  for (const auto& r : c.finished) length = std::max(length, r.generations.size());
  std::vector<double> running(c.finished.size(), -std::numeric_limits<double>::infinity());
  for (std::size_t g = 0; g < length; ++g) {
    std::vector<double> best, so_far;
    for (std::size_t r = 0; r < c.finished.size(); ++r) {
      const auto& gens = c.finished[r].generations;
      if (g < gens.size()) {
        best.push_back(gens[g].best);
        running[r] = std::max(running[r], gens[g].best);
      } else if (c.finished[r].stopped.empty()) {
        continue;
      }
      so_far.push_back(running[r]);
    }
    const Summary s = summarise(best);
    k.x.push_back(static_cast<double>(g));
    k.max.push_back(best.empty() ? kNaN : s.max);
    k.mean.push_back(best.empty() ? kNaN : s.mean);
    k.lo.push_back(best.empty() ? kNaN : s.mean - s.sd);
    k.hi.push_back(best.empty() ? kNaN : s.mean + s.sd);
    k.so_far.push_back(so_far.empty() ? kNaN : summarise(so_far).mean);
  }
  return k;
}

std::string who(const store::StoredExperiment& e) {
  return e.condition ? fmt::format("condition {} of study {} (experiment {})", e.condition->name, e.condition->study,
                                   e.name)
                     : fmt::format("experiment {}", e.name);
}

svg::Figure fitness_figure(const store::StoredExperiment& e) {
  svg::Figure f;
  f.title = fmt::format("Best fitness of each generation: {}", who(e));
  svg::Panel max{"maximum over runs", "generation", "fitness", {}, {}, {}, true};
  svg::Panel mean{"mean over runs", "generation", "fitness", {}, {}, {}, true};
  svg::Panel so_far{"best so far (mean over runs)", "generation", "fitness", {}, {}, {}, true};
  const bool bands = e.controllers.size() <= kMostBands;
  for (std::size_t i = 0; i < e.controllers.size(); ++i) {
    const store::StoredController& c = e.controllers[i];
    if (c.finished.empty()) continue;
    const Curves k = curves(c);
    max.lines.push_back({c.name, i, k.x, k.max, {}, {}, false, false, {}});
    mean.lines.push_back({c.name, i, k.x, k.mean, bands ? k.lo : std::vector<double>{},
                          bands ? k.hi : std::vector<double>{}, false, false, {}});
    so_far.lines.push_back({c.name, i, k.x, k.so_far, {}, {}, false, false, {}});
    f.legend.push_back({c.name, i, {}});
  }
  f.panels = {max, mean, so_far};
  f.note = fmt::format("Over the finished runs{}.", bands ? "; band: ± one standard deviation across runs" : "");
  return f;
}

svg::Figure box_figure(const store::StoredExperiment& e) {
  svg::Figure f;
  f.title = fmt::format("Best fitness of each run: {}", who(e));
  svg::Panel p{"", "controller", "best fitness", {}, {}, {}, false};
  for (std::size_t i = 0; i < e.controllers.size(); ++i) {
    p.boxes.push_back({e.controllers[i].name, i, p.categories.size(), best_fitness(e.controllers[i])});
    p.categories.push_back(e.controllers[i].name);
  }
  f.panels = {p};
  f.columns = 1;
  f.panel_width = std::max(340.0, 70.0 * static_cast<double>(p.categories.size()) + 80.0);
  f.note = "Box: quartiles; whiskers: lowest and highest run; bar: median; dots: runs.";
  return f;
}

// What the optimizers reported after each generation (CMA-ES's sigma, ...): one panel per
// metric, for each controller the median over its finished runs with their range as a band;
// no figure when no optimizer reported anything.
std::optional<svg::Figure> metrics_figure(const store::StoredExperiment& e) {
  std::vector<std::string> names;   // as first reported
  for (const auto& c : e.controllers)
    for (const auto& r : c.finished)
      for (const auto& g : r.generations)
        for (const evo::Metric& m : g.metrics)
          if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
  if (names.empty()) return std::nullopt;
  svg::Figure f;
  f.title = fmt::format("What each optimizer reported: {}", who(e));
  for (const std::string& name : names) {
    svg::Panel p{name, "generation", name, {}, {}, {}, true};
    for (std::size_t i = 0; i < e.controllers.size(); ++i) {
      const store::StoredController& c = e.controllers[i];
      svg::Line l{fmt::format("{} ({})", c.name, c.algorithm), i, {}, {}, {}, {}, false, false, {}};
      std::size_t length = 0;
      for (const auto& r : c.finished) length = std::max(length, r.generations.size());
      for (std::size_t g = 0; g < length; ++g) {
        std::vector<double> values;
        for (const auto& r : c.finished)
          if (g < r.generations.size())
            for (const evo::Metric& m : r.generations[g].metrics)
              if (m.name == name && std::isfinite(m.value)) values.push_back(m.value);
        if (values.empty()) continue;
        const Summary s = summarise(values);
        l.x.push_back(static_cast<double>(g));
        l.y.push_back(s.median);
        l.lo.push_back(s.min);
        l.hi.push_back(s.max);
      }
      if (!l.x.empty()) p.lines.push_back(std::move(l));
    }
    f.panels.push_back(std::move(p));
  }
  for (std::size_t i = 0; i < e.controllers.size(); ++i)
    if (!e.controllers[i].finished.empty())
      f.legend.push_back({fmt::format("{} ({})", e.controllers[i].name, e.controllers[i].algorithm), i, {}});
  f.note = "Over the finished runs: median of each generation; band: lowest to highest run.";
  return f;
}

// Controllers of the conditions in the order they first appear: their series' style.
std::vector<std::string> controllers_of(const std::vector<const store::StoredExperiment*>& conditions) {
  std::vector<std::string> names;
  for (const auto* e : conditions)
    for (const auto& c : e->controllers)
      if (std::find(names.begin(), names.end(), c.name) == names.end()) names.push_back(c.name);
  return names;
}

svg::Figure study_box_figure(const std::vector<const store::StoredExperiment*>& conditions) {
  svg::Figure f;
  f.title = fmt::format("Best fitness of each run, by condition: study {}", conditions.front()->condition->study);
  const std::vector<std::string> names = controllers_of(conditions);
  for (std::size_t k = 0; k < names.size(); ++k) {
    svg::Panel p{names[k], "condition", "best fitness", {}, {}, {}, false};
    for (const auto* e : conditions) {
      p.categories.push_back(e->condition->name);
      for (const auto& c : e->controllers)
        if (c.name == names[k]) p.boxes.push_back({c.name, k, p.categories.size() - 1, best_fitness(c)});
    }
    f.panels.push_back(std::move(p));
  }
  f.panel_width = std::max(340.0, 34.0 * static_cast<double>(conditions.size()) + 80.0);
  f.columns = std::max<std::size_t>(1, static_cast<std::size_t>(1100.0 / f.panel_width));
  f.note = "Box: quartiles; whiskers: lowest and highest run; bar: median; dots: runs.";
  return f;
}

// The points of sweep `sweep`: final best fitness against its first swept setting, one
// line per controller (and per value of the other swept settings, in a grid).
svg::Figure sweep_figure(const std::vector<const store::StoredExperiment*>& points) {
  const store::StoredCondition& first = *points.front()->condition;
  std::size_t axis = 0;
  while (axis < first.settings.size() && !first.settings[axis].swept) ++axis;
  const std::string key = axis < first.settings.size() ? first.settings[axis].key : "value";
  const bool numeric = std::all_of(points.begin(), points.end(), [&](const auto* e) {
    return axis < e->condition->settings.size() && e->condition->settings[axis].x.has_value();
  });
  svg::Figure f;
  f.title = fmt::format("Final best fitness against {}: study {}, sweep of {}", key, first.study, points.front()->name);
  const std::string unit = numeric ? first.settings[axis].x_unit : "";
  svg::Panel p{"", unit.empty() ? key : fmt::format("{} ({})", key, unit), "best fitness of a run", {}, {}, {}, false};
  // Where each point goes on the x axis.
  std::vector<double> xs;
  for (const auto* e : points) {
    const eval::ConditionSetting& s = e->condition->settings.at(axis);
    if (numeric) {
      xs.push_back(*s.x);
      continue;
    }
    auto at = std::find(p.categories.begin(), p.categories.end(), s.value);
    if (at == p.categories.end()) at = p.categories.insert(at, s.value);
    xs.push_back(static_cast<double>(at - p.categories.begin()));
  }
  // A series per controller and values of the other swept settings.
  std::map<std::string, std::size_t> series_of;
  const std::vector<std::string> names = controllers_of(points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string others;
    for (std::size_t k = 0; k < points[i]->condition->settings.size(); ++k)
      if (k != axis && points[i]->condition->settings[k].swept)
        others += fmt::format(", {}={}", points[i]->condition->settings[k].key, points[i]->condition->settings[k].value);
    for (const auto& c : points[i]->controllers) {
      const std::vector<double> best = best_fitness(c);
      if (best.empty()) continue;
      const std::string label = c.name + others;
      auto [it, fresh] = series_of.try_emplace(label, p.lines.size());
      if (fresh) {
        const auto style = static_cast<std::size_t>(std::find(names.begin(), names.end(), c.name) - names.begin());
        const std::size_t variant = others.empty() ? 0 : series_of.size() - 1;
        p.lines.push_back({label, others.empty() ? style : variant, {}, {}, {}, {}, true, true, {}});
        f.legend.push_back({label, p.lines.back().style, {}});
      }
      const Summary s = summarise(best);
      svg::Line& l = p.lines[it->second];
      l.x.push_back(xs[i]);
      l.y.push_back(s.mean);
      l.lo.push_back(s.mean - s.sd);
      l.hi.push_back(s.mean + s.sd);
    }
  }
  // Along the axis, whatever order the points were listed in.
  for (svg::Line& l : p.lines) {
    std::vector<std::size_t> order(l.x.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return l.x[a] < l.x[b]; });
    svg::Line sorted = l;
    for (std::size_t i = 0; i < order.size(); ++i) {
      sorted.x[i] = l.x[order[i]];
      sorted.y[i] = l.y[order[i]];
      sorted.lo[i] = l.lo[order[i]];
      sorted.hi[i] = l.hi[order[i]];
    }
    l = std::move(sorted);
  }
  f.panels = {p};
  f.columns = 1;
  f.panel_width = 520.0;
  f.panel_height = 320.0;
  f.note = "Points: mean over runs of each run's best fitness; bars: ± one standard deviation.";
  return f;
}

}  // namespace

std::vector<NamedFigure> experiment_figures(const store::StoredExperiment& e, const std::string& stem) {
  const svg::Figure fitness = fitness_figure(e);
  const svg::Figure box = box_figure(e);
  std::vector<NamedFigure> out = {{stem + "-fitness.svg", fitness.title, svg::render(fitness)},
                                  {stem + "-best.svg", box.title, svg::render(box)}};
  for (NamedFigure& f : usage_figures(e, stem)) out.push_back(std::move(f));
  if (const auto metrics = metrics_figure(e)) out.push_back({stem + "-metrics.svg", metrics->title, svg::render(*metrics)});
  for (NamedFigure& f : member_figures(e, stem)) out.push_back(std::move(f));
  for (NamedFigure& f : network_figures(e, stem)) out.push_back(std::move(f));
  return out;
}

std::vector<NamedFigure> study_figures(const std::vector<const store::StoredExperiment*>& conditions,
                                       const std::string& stem) {
  std::vector<NamedFigure> out;
  if (conditions.empty() || !conditions.front()->condition) return out;
  const svg::Figure box = study_box_figure(conditions);
  out.push_back({stem + "-best-by-condition.svg", box.title, svg::render(box)});
  std::map<int, std::vector<const store::StoredExperiment*>> sweeps;
  for (const auto* e : conditions)
    if (e->condition && e->condition->sweep) sweeps[*e->condition->sweep].push_back(e);
  for (const auto& [index, points] : sweeps) {
    const svg::Figure f = sweep_figure(points);
    out.push_back({sweeps.size() == 1 ? stem + "-sweep.svg" : fmt::format("{}-sweep-{}.svg", stem, index + 1), f.title,
                   svg::render(f)});
  }
  return out;
}

}  // namespace esc::report
