#include "runtime/report/map_figure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "runtime/report/markup.hpp"
#include "runtime/report/svg_plot.hpp"

namespace esc::report {

namespace {

std::string px(double v) { return fmt::format("{:.1f}", v); }

}  // namespace

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

std::string render_map(const MapFigure& m) {
  constexpr double left = 62, top = 34, side = 360, bar = 14, gap = 18, right = 70, bottom = 64;
  const double width = std::max(left + side + gap + bar + right, svg::title_width(m.title.size()));
  constexpr double note_line = 14.0;   // the note is 11-pixel text
  const std::vector<std::string> note = svg::note_lines(m.note, width, 11.0);
  const double height =
      top + side + bottom + note_line * static_cast<double>(std::max<std::size_t>(note.size(), 1) - 1);
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
  const auto x_of = [&](const UnitPoint& p) { return px(left + p[0] * side); };
  const auto y_of = [&](const UnitPoint& p) { return px(top + (1 - p[1]) * side); };
  const auto at = [&](const UnitPoint& p) { return x_of(p) + "," + y_of(p); };
  for (const std::vector<UnitPoint>& solid : m.solids) {
    std::string points;
    for (const UnitPoint& p : solid) {
      if (!points.empty()) points += ' ';
      points += at(p);
    }
    out += fmt::format("<polygon points=\"{}\" fill=\"#333\"/>\n", points);
  }
  if (m.border) {
    const auto& [a, b] = *m.border;
    out += fmt::format("<polygon points=\"{} {} {} {}\" fill=\"none\" stroke=\"#333\" stroke-width=\"2\"/>\n", at(a),
                       at({b[0], a[1]}), at(b), at({a[0], b[1]}));
  }
  if (m.mark)
    out += fmt::format("<circle cx=\"{0}\" cy=\"{1}\" r=\"7\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>"
                       "<circle cx=\"{0}\" cy=\"{1}\" r=\"2.5\" fill=\"#d62728\"/>\n", x_of(*m.mark), y_of(*m.mark));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", px(left),
                     px(top), px(side), px(side));
  // Ticks at the declared ranges' nice values.
  const auto axis_ticks = [&](const evo::Bounds& r, bool x) {
    const std::vector<double> ticks = svg::nice_ticks(r.lower, r.upper);
    for (const double v : ticks) {
      if (v < r.lower - 1e-12 * std::abs(r.upper - r.lower) || v > r.upper + 1e-12 * std::abs(r.upper - r.lower))
        continue;
      const double u = (v - r.lower) / (r.upper - r.lower) * side;
      out += x ? fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(left + u),
                             px(top + side + 15), svg::tick_label(v, svg::tick_step(ticks)))
               : fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", px(left - 5),
                             px(top + side - u + 4), svg::tick_label(v, svg::tick_step(ticks)));
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
  const auto end_label = [&](double v) {
    return m.log_counts ? fmt::format("{:.0f}", std::pow(10.0, v)) : svg::tick_label(v);
  };
  const double bx = left + side + gap;
  for (int i = 0; i < 64; ++i)
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", px(bx),
                       px(top + side * (1 - (i + 1) / 64.0)), px(bar), px(side / 64.0 + 0.3), viridis(i / 63.0));
  out += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n<text x=\"{}\" y=\"{}\">{}</text>\n", px(bx + bar + 4),
                     px(top + 8), end_label(hi), px(bx + bar + 4), px(top + side), end_label(lo));
  out += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     px(bx + bar + 40), px(top + side / 2), escape_markup(m.value_title));
  for (std::size_t i = 0; i < note.size(); ++i)
    out += fmt::format("<text x=\"8\" y=\"{}\" fill=\"#555\">{}</text>\n",
                       px(height - 10 - note_line * static_cast<double>(note.size() - 1 - i)), escape_markup(note[i]));
  out += "</svg>\n";
  return out;
}

}  // namespace esc::report
