#include "runtime/report/usage_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "runtime/report/svg_plot.hpp"

namespace esc::report {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// More lines than this in a panel are drawn one per library.
constexpr std::size_t kMostLines = 8;
constexpr double kStepsScale = 1e4;

// Calls per 10,000 steps of `indices` together in a generation's best evaluation; NaN for
// a generation stored without usage.
double calls(const eval::GenerationStats& g, const std::vector<std::size_t>& indices) {
  if (g.usage.steps_total <= 0) return kNaN;
  std::int64_t steps = 0;
  for (const std::size_t i : indices) {
    if (i >= g.usage.best.size()) return kNaN;
    steps += g.usage.best[i];
  }
  return kStepsScale * static_cast<double>(steps) / static_cast<double>(g.usage.steps_total);
}

// The median over the finished runs of a line's calls, generation by generation, with the
// band between the quartiles: calls are skewed (a behavior most runs never call and one run
// calls all the time), which a mean with ± one sd drew as a band below zero, cut off.
svg::Line curve(const store::StoredController& c, const UsageLine& line, std::size_t style) {
  svg::Line out{line.label, style, {}, {}, {}, {}, false, false, {}};
  std::size_t length = 0;
  for (const auto& r : c.finished) length = std::max(length, r.generations.size());
  for (std::size_t g = 0; g < length; ++g) {
    std::vector<double> values;
    for (const auto& r : c.finished) {
      if (g >= r.generations.size()) continue;
      const double v = calls(r.generations[g], line.indices);
      if (!std::isnan(v)) values.push_back(v);
    }
    std::sort(values.begin(), values.end());
    out.x.push_back(static_cast<double>(g));
    out.y.push_back(values.empty() ? kNaN : svg::quantile(values, 0.5));
    out.lo.push_back(values.empty() ? kNaN : svg::quantile(values, 0.25));
    out.hi.push_back(values.empty() ? kNaN : svg::quantile(values, 0.75));
  }
  return out;
}

bool has_usage(const store::StoredController& c) {
  if (c.actions.empty()) return false;
  for (const auto& r : c.finished)
    for (const auto& g : r.generations)
      if (!g.usage.empty()) return true;
  return false;
}

}  // namespace

std::vector<UsagePanel> usage_panels(const store::StoredController& c) {
  const bool known = c.choices.size() == c.actions.size();
  const auto useless = [&](std::size_t i) { return known && c.choices[i].useless; };
  std::vector<UsagePanel> panels;
  bool marked = false;
  for (std::size_t i = 0; i < c.actions.size(); ++i) marked = marked || useless(i);
  for (const bool of_useless : {false, true}) {
    UsagePanel p{marked ? (of_useless ? "useless behaviors" : "useful behaviors") : "behaviors", false, {}};
    for (std::size_t i = 0; i < c.actions.size(); ++i)
      if (useless(i) == of_useless) p.lines.push_back({c.actions[i], {i}});
    if (p.lines.size() > kMostLines) {
      std::map<std::string, std::vector<std::size_t>> by_library;
      std::vector<std::string> order;
      for (const UsageLine& l : p.lines) {
        const std::size_t i = l.indices.front();
        const std::string key = known && !c.choices[i].library.empty() ? c.choices[i].library : l.label;
        if (!by_library.contains(key)) order.push_back(key);
        by_library[key].push_back(i);
      }
      p.lines.clear();
      p.by_library = true;
      for (const std::string& key : order) {
        const std::vector<std::size_t>& indices = by_library[key];
        p.lines.push_back(
            {indices.size() > 1 ? fmt::format("{} ({} behaviors)", key, indices.size()) : key, indices});
      }
    }
    if (!p.lines.empty()) panels.push_back(std::move(p));
  }
  return panels;
}

std::vector<NamedFigure> usage_figures(const store::StoredExperiment& e, const std::string& stem) {
  std::vector<NamedFigure> out;
  for (const store::StoredController& c : e.controllers) {
    if (!has_usage(c)) continue;
    svg::Figure f;
    f.title = fmt::format("Calls per 10,000 steps as generations go by: {} in {}", c.name,
                          e.condition ? fmt::format("condition {} of study {}", e.condition->name, e.condition->study)
                                      : fmt::format("experiment {}", e.name));
    f.columns = 2;
    std::size_t style = 0;
    for (const UsagePanel& p : usage_panels(c)) {
      svg::Panel panel{p.title, "generation", "calls per 10,000 steps", {}, {}, {}, true};
      for (const UsageLine& l : p.lines) {
        panel.lines.push_back(curve(c, l, style));
        f.legend.push_back({l.label, style, {}});
        ++style;
      }
      f.panels.push_back(std::move(panel));
    }
    f.note = "In each generation's best evaluation; line: median over the finished runs; band: from the first "
             "to the third quartile across runs.";
    out.push_back({fmt::format("{}-usage-{}.svg", stem, c.name), f.title, svg::render(f)});
  }
  return out;
}

}  // namespace esc::report
