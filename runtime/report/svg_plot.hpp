#pragma once
// A small plotting module that writes standalone SVG, for figures that go into papers and
// documentation as they are (`esc report` writes them to DIR/figures/ and shows the same in
// the report): panels with axes and nice ticks on the data's own scale (never forced to
// include 0), lines with optional bands or error bars, box plots, categorical or numeric x
// axes, and one legend outside the panels. Series are told apart by colour and dash
// together (12 colours x 3 dashes), so 24 and more stay distinct.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace esc::report::svg {

struct Style {
  std::string colour;   // "#1f77b4"
  std::string dash;     // SVG stroke-dasharray; "" for solid
};

// The style of series `i`: colours first, then the same colours dashed.
[[nodiscard]] Style series_style(std::size_t i);

// Tick positions at 1, 2 or 5 times a power of ten, covering [lo, hi] with about `target`
// intervals; the first tick is at or below lo and the last at or above hi.
[[nodiscard]] std::vector<double> nice_ticks(double lo, double hi, int target = 5);

// A tick's label: the shortest decimal that names it (no trailing zeros, no `-0`), with
// digits enough to tell it from its neighbours `step` away (a narrow range far from zero).
[[nodiscard]] std::string tick_label(double v, double step = 0.0);

// The step between consecutive ticks, 0 for fewer than two.
[[nodiscard]] double tick_step(const std::vector<double>& ticks);

struct Line {
  std::string label;
  std::size_t style = 0;
  std::vector<double> x, y;         // NaN in y leaves a gap
  std::vector<double> lo, hi;       // empty, or one per point: a band, or error bars
  bool error_bars = false;          // lo/hi drawn as bars at each point rather than a band
  bool markers = false;
  std::string dash;                 // overrides the style's dash when not empty
  bool joined = true;               // false: the markers alone (a scatter)
};

// A box per value set: quartiles (linear interpolation between order statistics), the
// median, whiskers from the lowest to the highest value, and every value as a dot.
struct Box {
  std::string label;
  std::size_t style = 0;
  std::size_t category = 0;         // where on the categorical x axis
  std::vector<double> values;
};

struct Panel {
  std::string title;
  std::string x_title, y_title;
  // Non-empty: the x axis is categorical, x = the category's index.
  std::vector<std::string> categories;
  std::vector<Line> lines;
  std::vector<Box> boxes;
  bool x_whole = false;             // ticks at whole numbers only (generations)
};

struct LegendEntry {
  std::string label;
  std::size_t style = 0;
  std::string dash;                 // overrides the style's dash when not empty
};

// Panels in rows of `columns`, one legend to the right of them all.
struct Figure {
  std::string title;
  std::vector<Panel> panels;
  std::size_t columns = 3;
  double panel_width = 340.0;
  double panel_height = 250.0;
  std::vector<LegendEntry> legend;
  std::string note;                 // a line under the figure (what the lines and bands are)
};

[[nodiscard]] std::string render(const Figure& figure);

// How wide a figure's title is drawn (13-pixel bold DejaVu Sans, the widest of the fonts
// the figures name: about 0.66 em a character), so that a figure is made wide enough for it.
[[nodiscard]] constexpr double title_width(std::size_t characters) noexcept {
  return 8.6 * static_cast<double>(characters) + 16.0;
}

// A figure's note in as many lines as a figure `width` pixels wide needs, for text of
// `font_px` pixels (DejaVu Sans), broken at spaces (a longer word stands alone).
[[nodiscard]] std::vector<std::string> note_lines(const std::string& text, double width, double font_px);

// The q-quantile of sorted values, interpolated linearly (NumPy's default).
[[nodiscard]] double quantile(const std::vector<double>& sorted, double q);

}  // namespace esc::report::svg
