#include "runtime/report/member_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <functional>
#include <numeric>
#include <optional>

#include <fmt/format.h>

#include "runtime/report/map_figure.hpp"
#include "runtime/report/markup.hpp"
#include "runtime/report/svg_plot.hpp"

namespace esc::report {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The controller's finished run with the highest best fitness (the earliest on a tie).
const eval::RunResult* best_run(const store::StoredController& c) {
  const eval::RunResult* best = nullptr;
  for (const eval::RunResult& r : c.finished)
    if (best == nullptr || r.best_fitness > best->best_fitness) best = &r;
  return best;
}

int last_generation(const eval::RunResult& r) { return static_cast<int>(r.generations.size()) - 1; }

// The tiles of a grid archive: the first two descriptors' bins (a third folded by the best).
std::vector<Tile> grid_tiles(const eval::MemberLayout& l, const std::vector<store::StoredMember>& elites) {
  const std::size_t bx = l.bins[0], by = l.bins.size() > 1 ? l.bins[1] : 1;
  const std::size_t bz = l.bins.size() > 2 ? l.bins[2] : 1;
  std::vector<double> best(bx * by, kNan);
  for (const store::StoredMember& m : elites) {
    // Row-major, the first descriptor slowest (grid.hpp).
    const auto cell = static_cast<std::size_t>(m.cell);
    const std::size_t i = cell / (by * bz), j = (cell / bz) % by;
    double& b = best[i * by + j];
    if (!m.objectives.empty() && (std::isnan(b) || m.objectives[0] > b)) b = m.objectives[0];
  }
  std::vector<Tile> tiles;
  for (std::size_t i = 0; i < bx; ++i)
    for (std::size_t j = 0; j < by; ++j)
      tiles.push_back({static_cast<double>(i) / static_cast<double>(bx), static_cast<double>(j) / static_cast<double>(by),
                       static_cast<double>(i + 1) / static_cast<double>(bx),
                       static_cast<double>(j + 1) / static_cast<double>(by), best[i * by + j]});
  return tiles;
}

// The Voronoi cells of a CVT over two descriptors, as a raster of `n` x `n` squares, each
// the value of its nearest centroid's elite; consecutive squares of a row with one value
// are one tile.
std::vector<Tile> voronoi_tiles(const eval::MemberLayout& l, const std::vector<store::StoredMember>& elites,
                                std::size_t n = 150) {
  const std::size_t k = l.centroids.size() / 2;
  std::vector<double> value(k, kNan);
  for (const store::StoredMember& m : elites)
    if (static_cast<std::size_t>(m.cell) < k && !m.objectives.empty()) value[static_cast<std::size_t>(m.cell)] = m.objectives[0];
  std::vector<Tile> tiles;
  const double d = 1.0 / static_cast<double>(n);
  for (std::size_t row = 0; row < n; ++row) {
    const double y = (static_cast<double>(row) + 0.5) * d;
    std::size_t run_start = 0, run_cell = k;
    for (std::size_t col = 0; col <= n; ++col) {
      std::size_t nearest = k;
      if (col < n) {
        const double x = (static_cast<double>(col) + 0.5) * d;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < k; ++c) {
          const double dx = l.centroids[2 * c] - x, dy = l.centroids[2 * c + 1] - y, dist = dx * dx + dy * dy;
          if (dist < best) best = dist, nearest = c;
        }
      }
      if (col == n || nearest != run_cell) {
        if (col > 0 && run_cell < k)
          tiles.push_back({static_cast<double>(run_start) * d, static_cast<double>(row) * d,
                           static_cast<double>(col) * d, static_cast<double>(row + 1) * d, value[run_cell]});
        run_start = col;
        run_cell = nearest;
      }
    }
  }
  return tiles;
}

std::string range_text(const evo::Bounds& b) { return fmt::format("[{}, {}]", svg::tick_label(b.lower), svg::tick_label(b.upper)); }

// Points over the first two descriptors (an archive of behaviors, or elites off a plane).
svg::Figure points_figure(const store::StoredController& c, const std::vector<store::StoredMember>& points,
                          const std::string& title, const std::string& what) {
  const eval::MemberLayout& l = c.members->layout;
  svg::Panel p{"", l.descriptors[0], l.descriptors.size() > 1 ? l.descriptors[1] : "", {}, {}, {}, false};
  svg::Line line{what, 0, {}, {}, {}, {}, false, true, {}, false};
  for (const store::StoredMember& m : points) {
    if (m.descriptors.empty()) continue;
    line.x.push_back(m.descriptors[0]);
    line.y.push_back(m.descriptors.size() > 1 ? m.descriptors[1] : 0.0);
  }
  p.lines.push_back(std::move(line));
  svg::Figure f;
  f.title = title;
  f.panels = {std::move(p)};
  f.columns = 1;
  f.panel_width = 420.0;
  f.panel_height = 380.0;
  f.note = fmt::format("{} points; descriptor ranges {}", points.size(),
                       l.descriptor_ranges.empty() ? std::string()
                                                   : range_text(l.descriptor_ranges[0]) +
                                                         (l.descriptor_ranges.size() > 1
                                                              ? " x " + range_text(l.descriptor_ranges[1])
                                                              : std::string()));
  return f;
}

std::optional<NamedFigure> archive_figure(const store::StoredController& c, const std::string& who,
                                          const std::string& file) {
  const eval::MemberLayout& l = c.members->layout;
  const eval::RunResult* run = best_run(c);
  if (run == nullptr || l.descriptors.empty()) return std::nullopt;
  const std::vector<store::StoredMember> elites = store::members_at(*c.members, run->run, last_generation(*run));
  const std::string when = fmt::format("run {} after generation {}", run->run + 1, last_generation(*run));
  const bool map = !l.objectives.empty() && (!l.bins.empty() || (l.descriptors.size() == 2 && !l.centroids.empty()));
  if (!map) {
    const std::string title = fmt::format("{}'s archive, {}", who, when);
    const svg::Figure f = points_figure(c, elites, title, l.objectives.empty() ? "behavior archived" : "elite");
    return NamedFigure{file, title, svg::render(f)};
  }
  MapFigure m;
  m.x_title = l.descriptors[0];
  m.x_range = l.descriptor_ranges[0];
  if (l.descriptors.size() > 1) {
    m.y_title = l.descriptors[1];
    m.y_range = l.descriptor_ranges[1];
  }
  m.value_title = l.objectives[0];
  std::size_t cells = 0;
  if (!l.bins.empty()) {
    m.tiles = grid_tiles(l, elites);
    cells = std::accumulate(l.bins.begin(), l.bins.end(), std::size_t{1}, std::multiplies<>());
    m.title = fmt::format("{}'s archive (grid), {}", who, when);
  } else {
    m.tiles = voronoi_tiles(l, elites);
    cells = l.centroids.size() / 2;
    m.title = fmt::format("{}'s archive (CVT, Voronoi cells), {}", who, when);
  }
  m.note = fmt::format("{} of {} cells filled ({:.1f} %); colour: the elite's {}; grey: empty{}", elites.size(), cells,
                       100.0 * static_cast<double>(elites.size()) / static_cast<double>(cells), l.objectives[0],
                       l.bins.size() > 2 ? "; each square the best over the third descriptor" : "");
  return NamedFigure{file, m.title, render_map(m)};
}

std::optional<NamedFigure> front_figure(const store::StoredController& c, const std::string& who,
                                        const std::string& file) {
  const eval::MemberLayout& l = c.members->layout;
  if (l.objectives.size() < 2 || c.finished.empty()) return std::nullopt;
  const auto label = [&](std::size_t i) { return l.objectives[i] + (l.minimized[i] ? " (minimised)" : ""); };
  svg::Panel p{"", label(0), label(1), {}, {}, {}, false};
  svg::Figure f;
  for (std::size_t i = 0; i < c.finished.size(); ++i) {
    const eval::RunResult& r = c.finished[i];
    std::vector<store::StoredMember> front = store::members_at(*c.members, r.run, last_generation(r));
    std::sort(front.begin(), front.end(), [](const auto& a, const auto& b) { return a.objectives[0] < b.objectives[0]; });
    svg::Line line{fmt::format("run {}", r.run + 1), i, {}, {}, {}, {}, false, true, {}, true};
    for (const store::StoredMember& m : front) {
      line.x.push_back(m.objectives[0]);
      line.y.push_back(m.objectives[1]);
    }
    p.lines.push_back(std::move(line));
    if (c.finished.size() <= 12) f.legend.push_back({fmt::format("run {}", r.run + 1), i, {}});
  }
  f.title = fmt::format("{}'s Pareto fronts after the last generation", who);
  f.panels = {std::move(p)};
  f.columns = 1;
  f.panel_width = 460.0;
  f.panel_height = 340.0;
  f.note = fmt::format("Each run's first front, objectives as measured{}.",
                       l.objectives.size() > 2 ? fmt::format("; the first two of {}", l.objectives.size()) : "");
  return NamedFigure{file, f.title, svg::render(f)};
}

}  // namespace

std::vector<NamedFigure> member_figures(const store::StoredExperiment& e, const std::string& stem) {
  std::vector<NamedFigure> out;
  for (const store::StoredController& c : e.controllers) {
    if (!c.members) continue;
    const std::string who = fmt::format("{} ({})", c.name, c.algorithm);
    const std::string file = fmt::format("{}-{}-{}.svg", stem, c.name, store::member_kind_name(c.members->layout.kind));
    auto f = c.members->layout.kind == evo::MemberKind::Front ? front_figure(c, who, file) : archive_figure(c, who, file);
    if (f) out.push_back(std::move(*f));
  }
  return out;
}

}  // namespace esc::report
