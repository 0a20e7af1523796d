#include "runtime/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "runtime/report/markup.hpp"

namespace esc::report::svg {

namespace {

// Tableau 10 and two more: distinct on screen and in print.
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#393b79", "#637939"};
constexpr const char* kDashes[] = {"", "6 3", "2 2"};
constexpr std::size_t kColourCount = std::size(kColours);

constexpr double kLeft = 58.0, kRight = 12.0, kTop = 26.0, kBottom = 42.0;
constexpr double kCharWidth = 7.0;   // of the 11-pixel DejaVu Sans text (0.63 em), roughly
constexpr double kTitleHeight = 26.0, kNoteHeight = 20.0, kNoteLine = 13.0, kLegendRow = 16.0;
constexpr double kNoteFont = 10.0;   // the note's text, in pixels

// `text` in lines of at most `chars` characters, broken at spaces (a longer word stands alone).
std::vector<std::string> wrapped(const std::string& text, std::size_t chars) {
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t space = std::min(text.find(' ', at), text.size());
    const std::string word = text.substr(at, space - at);
    if (!line.empty() && line.size() + 1 + word.size() > chars) lines.push_back(std::exchange(line, {}));
    line += (line.empty() ? "" : " ") + word;
    at = space + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string px(double v) { return fmt::format("{:.1f}", v); }

// A linear map from data to pixels.
struct Scale {
  double d0 = 0.0, d1 = 1.0, p0 = 0.0, p1 = 1.0;
  [[nodiscard]] double operator()(double v) const { return p0 + (v - d0) / (d1 - d0) * (p1 - p0); }
};

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  [[nodiscard]] bool empty() const { return lo > hi; }
};

// Ticks over the range, widened when it is a single value or empty; whole numbers only when
// `whole` (generations).
std::vector<double> ticks_for(Range r, bool whole = false) {
  if (r.empty()) r = {0.0, 1.0};
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    const double pad = whole ? 1.0 : std::max(1e-9, std::abs(r.lo) * 0.1 + (r.lo == 0.0 ? 1.0 : 0.0));
    r = {r.lo - pad, r.hi + pad};
  }
  std::vector<double> t = nice_ticks(r.lo, r.hi);
  if (whole && t.size() > 1 && t[1] - t[0] < 1.0) t = nice_ticks(r.lo, r.hi, static_cast<int>(std::ceil(r.hi - r.lo)));
  return t;
}

// The label of category `i`, rotated when the categories do not fit side by side.
bool rotated(const Panel& p, double width) {
  std::size_t longest = 0;
  for (const std::string& c : p.categories) longest = std::max(longest, c.size());
  return static_cast<double>(p.categories.size() * longest) * kCharWidth > width;
}

// Extra room under a panel for rotated category labels.
double label_room(const Panel& p, double width) {
  if (p.categories.empty() || !rotated(p, width)) return 0.0;
  std::size_t longest = 0;
  for (const std::string& c : p.categories) longest = std::max(longest, c.size());
  return static_cast<double>(longest) * kCharWidth * 0.6;
}

std::string stroke(const Style& s, const std::string& dash, double width) {
  const std::string& d = dash.empty() ? s.dash : dash;
  return fmt::format("stroke=\"{}\" stroke-width=\"{}\"{}", s.colour, px(width),
                     d.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", d));
}

void draw_line(std::string& out, const Line& l, const Scale& x, const Scale& y) {
  const Style s = series_style(l.style);
  const std::size_t n = std::min(l.x.size(), l.y.size());
  const bool ranged = l.lo.size() == n && l.hi.size() == n;
  if (ranged && !l.error_bars) {
    std::string points;
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(l.hi[i])) points += px(x(l.x[i])) + "," + px(y(l.hi[i])) + " ";
    for (std::size_t i = n; i-- > 0;)
      if (std::isfinite(l.lo[i])) points += px(x(l.x[i])) + "," + px(y(l.lo[i])) + " ";
    out += fmt::format("<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"0.13\" stroke=\"none\"/>\n", points, s.colour);
  }
  std::string path;
  bool pen_down = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(l.y[i])) {
      pen_down = false;
      continue;
    }
    path += fmt::format("{}{},{} ", pen_down ? "L" : "M", px(x(l.x[i])), px(y(l.y[i])));
    pen_down = true;
  }
  if (!path.empty() && l.joined)
    out += fmt::format("<path d=\"{}\" fill=\"none\" {} stroke-linejoin=\"round\"/>\n", path, stroke(s, l.dash, 1.6));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(l.y[i])) continue;
    if (ranged && l.error_bars && std::isfinite(l.lo[i]) && std::isfinite(l.hi[i])) {
      const double cx = x(l.x[i]);
      out += fmt::format("<path d=\"M{0},{1} L{0},{2} M{3},{1} L{4},{1} M{3},{2} L{4},{2}\" stroke=\"{5}\" "
                         "stroke-width=\"1.2\" fill=\"none\"/>\n",
                         px(cx), px(y(l.lo[i])), px(y(l.hi[i])), px(cx - 3), px(cx + 3), s.colour);
    }
    if (l.markers)
      out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2.8\" fill=\"{}\"/>\n", px(x(l.x[i])), px(y(l.y[i])), s.colour);
  }
}

void draw_box(std::string& out, const Box& b, double centre, double width, const Scale& y) {
  if (b.values.empty()) return;
  std::vector<double> v = b.values;
  std::sort(v.begin(), v.end());
  const Style s = series_style(b.style);
  const double q1 = quantile(v, 0.25), q2 = quantile(v, 0.5), q3 = quantile(v, 0.75);
  out += fmt::format("<line x1=\"{0}\" x2=\"{0}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#444\" stroke-width=\"1\"/>\n",
                     px(centre), px(y(v.front())), px(y(v.back())));
  for (const double end : {v.front(), v.back()})
    out += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"#444\" stroke-width=\"1\"/>\n",
                       px(centre - width / 4), px(centre + width / 4), px(y(end)));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" fill-opacity=\"0.3\" stroke=\"{}\" "
                     "stroke-width=\"1.3\"/>\n",
                     px(centre - width / 2), px(y(q3)), px(width), px(std::max(0.5, y(q1) - y(q3))), s.colour, s.colour);
  out += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"#111\" stroke-width=\"2\"/>\n",
                     px(centre - width / 2), px(centre + width / 2), px(y(q2)));
  for (std::size_t i = 0; i < v.size(); ++i) {
    // Spread side by side (golden-ratio offsets) so that equal values stay visible.
    const double offset = (std::fmod(static_cast<double>(i) * 0.618034, 1.0) - 0.5) * width * 0.6;
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"2.2\" fill=\"#000\" fill-opacity=\"0.55\"/>\n",
                       px(centre + offset), px(y(v[i])));
  }
}

void draw_panel(std::string& out, const Panel& p, double left, double top, double width, double height,
                double extra_bottom) {
  const double x0 = left + kLeft, x1 = left + width - kRight;
  const double y0 = top + height - kBottom - extra_bottom, y1 = top + kTop;
  Range yr, xr;
  for (const Line& l : p.lines) {
    for (const double v : l.y) yr.add(v);
    for (const double v : l.lo) yr.add(v);
    for (const double v : l.hi) yr.add(v);
    for (const double v : l.x) xr.add(v);
  }
  for (const Box& b : p.boxes)
    for (const double v : b.values) yr.add(v);
  const std::vector<double> yt = ticks_for(yr);
  const Scale y{yt.front(), yt.back(), y0, y1};
  const bool categorical = !p.categories.empty();
  const std::vector<double> xt = categorical ? std::vector<double>{} : ticks_for(xr, p.x_whole);
  const double n = static_cast<double>(std::max<std::size_t>(1, p.categories.size()));
  const Scale x = categorical ? Scale{-0.5, n - 0.5, x0, x1} : Scale{xt.front(), xt.back(), x0, x1};

  out += fmt::format("<g>\n<text x=\"{}\" y=\"{}\" font-weight=\"600\" font-size=\"12\">{}</text>\n", px(x0),
                     px(top + 16), escape_markup(p.title));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888\"/>\n", px(x0),
                     px(y1), px(x1 - x0), px(y0 - y1));
  for (const double t : yt) {
    out += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"#e4e4e4\"/>\n", px(x0), px(x1), px(y(t)));
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", px(x0 - 4), px(y(t) + 4),
                       tick_label(t, tick_step(yt)));
  }
  if (categorical) {
    const bool turn = rotated(p, x1 - x0);
    for (std::size_t i = 0; i < p.categories.size(); ++i) {
      const double cx = x(static_cast<double>(i));
      out += turn ? fmt::format("<text transform=\"translate({},{}) rotate(-35)\" text-anchor=\"end\">{}</text>\n",
                                px(cx + 3), px(y0 + 12), escape_markup(p.categories[i]))
                  : fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(cx), px(y0 + 15),
                                escape_markup(p.categories[i]));
    }
  } else {
    for (const double t : xt) {
      out += fmt::format("<line x1=\"{0}\" x2=\"{0}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#888\"/>\n", px(x(t)), px(y0),
                         px(y0 + 4));
      out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(x(t)), px(y0 + 15),
                         tick_label(t, tick_step(xt)));
    }
  }
  out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px((x0 + x1) / 2),
                     px(y0 + 32 + extra_bottom), escape_markup(p.x_title));
  out += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     px(left + 13), px((y0 + y1) / 2), escape_markup(p.y_title));
  // Boxes share their category's band side by side.
  std::vector<std::size_t> per_category(p.categories.size(), 0), placed(p.categories.size(), 0);
  for (const Box& b : p.boxes)
    if (b.category < per_category.size()) ++per_category[b.category];
  for (const Box& b : p.boxes) {
    if (b.category >= per_category.size()) continue;
    const double band = (x1 - x0) / n * 0.8;
    const double slot = band / static_cast<double>(per_category[b.category]);
    const double centre = x(static_cast<double>(b.category)) - band / 2 + slot * (static_cast<double>(placed[b.category]++) + 0.5);
    draw_box(out, b, centre, std::min(slot * 0.7, 40.0), y);
  }
  for (const Line& l : p.lines) draw_line(out, l, x, y);
  out += "</g>\n";
}

}  // namespace

Style series_style(std::size_t i) {
  return {kColours[i % kColourCount], kDashes[(i / kColourCount) % std::size(kDashes)]};
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo, hi};
  const double raw = (hi - lo) / std::max(1, target);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / magnitude;
  const double step = (norm < 1.5 ? 1.0 : norm < 3.0 ? 2.0 : norm < 7.0 ? 5.0 : 10.0) * magnitude;
  const double first = std::floor(lo / step + 1e-9), last = std::ceil(hi / step - 1e-9);
  std::vector<double> t;
  for (double k = first; k <= last && t.size() < 100; ++k) t.push_back(k * step);
  if (t.size() < 2) t = {first * step, (first + 1) * step};
  return t;
}

std::string tick_label(double v, double step) {
  if (std::abs(v) < (step > 0.0 ? 1e-6 * step : 1e-12)) return "0";
  int digits = 6;
  if (step > 0.0 && std::abs(v) > step)
    digits = std::clamp(static_cast<int>(std::floor(std::log10(std::abs(v))) - std::floor(std::log10(step))) + 1, 6, 17);
  return fmt::format("{:.{}g}", v, digits);
}

double tick_step(const std::vector<double>& ticks) { return ticks.size() < 2 ? 0.0 : ticks[1] - ticks[0]; }

std::vector<std::string> note_lines(const std::string& text, double width, double font_px) {
  const double char_width = kCharWidth * font_px / 11.0;
  return wrapped(text, static_cast<std::size_t>(std::max(20.0, (width - 16.0) / char_width)));
}

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = static_cast<double>(sorted.size() - 1) * q;
  const auto lo = static_cast<std::size_t>(std::floor(pos)), hi = static_cast<std::size_t>(std::ceil(pos));
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - static_cast<double>(lo));
}

std::string render(const Figure& f) {
  const std::size_t columns = std::max<std::size_t>(1, std::min(f.columns, f.panels.size()));
  const std::size_t rows = (f.panels.size() + columns - 1) / columns;
  double extra = 0.0;
  for (const Panel& p : f.panels) extra = std::max(extra, label_room(p, f.panel_width - kLeft - kRight));
  const double cell_height = f.panel_height + extra;
  std::size_t longest = 0;
  for (const LegendEntry& e : f.legend) longest = std::max(longest, e.label.size());
  const double legend_width = f.legend.empty() ? 0.0 : 44.0 + static_cast<double>(longest) * kCharWidth;
  const double top = f.title.empty() ? 4.0 : kTitleHeight;
  const double panels_height = static_cast<double>(rows) * cell_height;
  const double legend_height = static_cast<double>(f.legend.size()) * kLegendRow + 8.0;
  const double width = std::max(static_cast<double>(columns) * f.panel_width + legend_width, title_width(f.title.size()));
  const std::vector<std::string> note = note_lines(f.note, width, kNoteFont);
  const double note_height = note.empty() ? 4.0 : kNoteHeight + kNoteLine * static_cast<double>(note.size() - 1);
  const double height = top + std::max(panels_height, legend_height) + note_height;

  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"11\" fill=\"#222\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n",
      px(width), px(height));
  if (!f.title.empty())
    out += fmt::format("<text x=\"8\" y=\"18\" font-weight=\"600\" font-size=\"13\">{}</text>\n", escape_markup(f.title));
  for (std::size_t i = 0; i < f.panels.size(); ++i)
    draw_panel(out, f.panels[i], static_cast<double>(i % columns) * f.panel_width,
               top + static_cast<double>(i / columns) * cell_height, f.panel_width, f.panel_height + extra, extra);
  const double lx = static_cast<double>(columns) * f.panel_width + 8.0;
  for (std::size_t i = 0; i < f.legend.size(); ++i) {
    const LegendEntry& e = f.legend[i];
    const double ly = top + 14.0 + static_cast<double>(i) * kLegendRow;
    out += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" {3}/>\n", px(lx), px(lx + 28), px(ly - 4),
                       stroke(series_style(e.style), e.dash, 2.0));
    out += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", px(lx + 34), px(ly), escape_markup(e.label));
  }
  for (std::size_t i = 0; i < note.size(); ++i)
    out += fmt::format("<text x=\"8\" y=\"{}\" font-size=\"10\" fill=\"#555\">{}</text>\n",
                       px(height - 6 - kNoteLine * static_cast<double>(note.size() - 1 - i)), escape_markup(note[i]));
  out += "</svg>\n";
  return out;
}

}  // namespace esc::report::svg
