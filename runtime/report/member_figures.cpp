#include "runtime/report/member_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <functional>
#include <numeric>
#include <optional>

#include <fmt/format.h>

#include "runtime/report/markup.hpp"
#include "runtime/report/svg_plot.hpp"

namespace esc::report {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::string px(double v) { return fmt::format("{:.1f}", v); }

// The controller's finished run with the highest best fitness (the earliest on a tie).
const eval::RunResult* best_run(const store::StoredController& c) {
  const eval::RunResult* best = nullptr;
  for (const eval::RunResult& r : c.finished)
    if (best == nullptr || r.best_fitness > best->best_fitness) best = &r;
  return best;
}

int last_generation(const eval::RunResult& r) { return static_cast<int>(r.generations.size()) - 1; }

// Viridis at t in [0, 1] (matplotlib's, at 9 stops, interpolated linearly).
std::string viridis(double t) {
  static constexpr std::array<std::array<int, 3>, 9> stops{{{68, 1, 84}, {71, 44, 122}, {59, 81, 139},
                                                            {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                                            {92, 200, 99}, {170, 220, 50}, {253, 231, 37}}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(i);
  std::array<int, 3> c{};
  for (std::size_t k = 0; k < 3; ++k)
    c[k] = static_cast<int>(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
  return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
}

// A map of the descriptor plane: rectangles in unit coordinates, each with a value (NaN:
// empty), drawn over the two descriptors' declared ranges with a colour bar.
struct Tile {
  double x0, y0, x1, y1, value;
};

struct MapFigure {
  std::string title, x_title, y_title, value_title, note;
  evo::Bounds x_range, y_range;
  std::vector<Tile> tiles;
};

std::string render_map(const MapFigure& m) {
  constexpr double left = 62, top = 34, side = 360, bar = 14, gap = 18, right = 70, bottom = 64;
  // Wide enough for the title (13-pixel bold text, about 7.5 pixels a character).
  const double width = std::max(left + side + gap + bar + right, 16.0 + 7.5 * static_cast<double>(m.title.size()));
  const double height = top + side + bottom;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Tile& t : m.tiles)
    if (std::isfinite(t.value)) {
      lo = std::min(lo, t.value);
      hi = std::max(hi, t.value);
    }
  if (!(lo <= hi)) lo = 0, hi = 1;
  const double span = hi > lo ? hi - lo : 1.0;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"8\" y=\"18\" font-weight=\"600\" font-size=\"13\">{2}</text>\n",
      px(width), px(height), escape_markup(m.title));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#e6e6e6\"/>\n", px(left), px(top),
                     px(side), px(side));
  for (const Tile& t : m.tiles) {
    if (!std::isfinite(t.value)) continue;
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", px(left + t.x0 * side),
                       px(top + (1 - t.y1) * side), px((t.x1 - t.x0) * side + 0.3), px((t.y1 - t.y0) * side + 0.3),
                       viridis((t.value - lo) / span));
  }
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", px(left),
                     px(top), px(side), px(side));
  // Ticks at the declared ranges' nice values.
  const auto axis_ticks = [&](const evo::Bounds& r, bool x) {
    for (const double v : svg::nice_ticks(r.lower, r.upper)) {
      if (v < r.lower - 1e-12 * std::abs(r.upper - r.lower) || v > r.upper + 1e-12 * std::abs(r.upper - r.lower))
        continue;
      const double u = (v - r.lower) / (r.upper - r.lower) * side;
      out += x ? fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(left + u),
                             px(top + side + 15), svg::tick_label(v))
               : fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", px(left - 5),
                             px(top + side - u + 4), svg::tick_label(v));
    }
  };
  axis_ticks(m.x_range, true);
  if (!m.y_title.empty()) axis_ticks(m.y_range, false);
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(left + side / 2),
                     px(top + side + 32), escape_markup(m.x_title));
  if (!m.y_title.empty())
    out += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                       px(14), px(top + side / 2), escape_markup(m.y_title));
  // The colour bar, from lo (bottom) to hi.
  const double bx = left + side + gap;
  for (int i = 0; i < 64; ++i)
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", px(bx),
                       px(top + side * (1 - (i + 1) / 64.0)), px(bar), px(side / 64.0 + 0.3), viridis(i / 63.0));
  out += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n<text x=\"{}\" y=\"{}\">{}</text>\n", px(bx + bar + 4),
                     px(top + 8), svg::tick_label(hi), px(bx + bar + 4), px(top + side), svg::tick_label(lo));
  out += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     px(bx + bar + 40), px(top + side / 2), escape_markup(m.value_title));
  out += fmt::format("<text x=\"8\" y=\"{}\" fill=\"#555\">{}</text>\n</svg>\n", px(height - 10), escape_markup(m.note));
  return out;
}

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
