// The SVG plot module: ticks on the data's own scale, labels, styles that stay distinct
// for 24 series, escaping, gaps, boxes, categorical axes and a legend that grows.
#include "runtime/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "tests/report/helpers.hpp"

namespace esc::report::svg {
namespace {

using esc::report::test::count;

TEST(SvgPlot, NiceTicksCoverTheDataAtRoundSteps) {
  EXPECT_EQ(nice_ticks(0.3, 9.7), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  // Not from 0: the data's own range.
  const auto t = nice_ticks(593.9, 612.4);
  EXPECT_EQ(t.front(), 590.0);
  EXPECT_EQ(t.back(), 615.0);
  EXPECT_EQ(t[1] - t[0], 5.0);
  const auto small = nice_ticks(-0.013, 0.021);
  EXPECT_LE(small.front(), -0.013);
  EXPECT_GE(small.back(), 0.021);
  EXPECT_LE(small.size(), 10u);
}

TEST(SvgPlot, TickLabelsAreShort) {
  EXPECT_EQ(tick_label(0.1 + 0.2), "0.3");
  EXPECT_EQ(tick_label(-1e-15), "0");
  EXPECT_EQ(tick_label(250), "250");
  EXPECT_EQ(tick_label(-2.5), "-2.5");
}

// A narrow range far from zero (a fitness that barely moves) labelled each tick the same.
TEST(SvgPlot, TickLabelsOfANarrowRangeDiffer) {
  const std::vector<double> t = nice_ticks(1234.56701, 1234.56723);
  ASSERT_GE(t.size(), 3u);
  std::set<std::string> labels;
  for (const double v : t) labels.insert(tick_label(v, tick_step(t)));
  EXPECT_EQ(labels.size(), t.size());
  EXPECT_EQ(tick_label(1234.5671, 5e-5), "1234.5671");
  EXPECT_EQ(tick_label(250, 50), "250");
  EXPECT_EQ(tick_label(1e-20, 0.5), "0");
}

TEST(SvgPlot, TwentyFourSeriesHaveDistinctStyles) {
  std::set<std::pair<std::string, std::string>> seen;
  for (std::size_t i = 0; i < 24; ++i) seen.insert({series_style(i).colour, series_style(i).dash});
  EXPECT_EQ(seen.size(), 24u);
}

TEST(SvgPlot, BoxesAreDrawnOnTheDataScale) {
  Figure f;
  Panel p{"", "controller", "best fitness", {"CC", "SC"}, {}, {}, false};
  p.boxes.push_back({"CC", 0, 0, {600.5, 604.0, 598.2}});
  p.boxes.push_back({"SC", 1, 1, {593.9, 612.4}});
  f.panels = {p};
  const std::string svg = render(f);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find(">590</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">0</text>"), std::string::npos);
  EXPECT_EQ(count(svg, "<rect x="), 3u);          // the frame and two boxes
  EXPECT_EQ(count(svg, "<circle"), 5u);           // every run
}

TEST(SvgPlot, LinesBreakAtNaNAndEscapeTheirText) {
  Figure f;
  f.title = "a <b> & \"c\"";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Panel p{"t", "generation", "fitness", {}, {}, {}, true};
  p.lines.push_back({"one", 0, {0, 1, 2, 3, 4}, {1, 2, nan, 4, 5}, {}, {}, false, false, {}});
  f.panels = {p};
  f.legend = {{"one & only", 0, {}}};
  const std::string svg = render(f);
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(svg.find("one &amp; only"), std::string::npos);
  const std::size_t path = svg.find("<path d=\"");
  ASSERT_NE(path, std::string::npos);
  const std::string d = svg.substr(path, svg.find('"', path + 9) - path);
  EXPECT_EQ(count(d, "M"), 2u);
  // Whole generations only.
  EXPECT_EQ(svg.find(">0.5</text>"), std::string::npos);
}

// A note longer than the figure is wide goes on as many lines as it needs, every word kept;
// a short one stays one line, where it always was.
TEST(SvgPlot, ALongNoteWrapsWithinTheFigure) {
  Figure f;
  Panel p{"t", "generation", "fitness", {}, {}, {}, true};
  p.lines.push_back({"one", 0, {0, 1}, {1, 2}, {}, {}, false, false, {}});
  f.panels = {p};
  f.note = "short";
  const std::string one = render(f);
  EXPECT_EQ(count(one, "font-size=\"10\" fill=\"#555\""), 1u);
  std::string words = "quartile";
  for (int i = 1; i < 40; ++i) words.append(" quartile");
  f.note = words;
  const std::string svg = render(f);
  const std::size_t lines = count(svg, "font-size=\"10\" fill=\"#555\"");
  EXPECT_GE(lines, 3u) << "360 characters under one panel of " << f.panel_width << " pixels";
  EXPECT_EQ(count(svg, "quartile"), 40u);
  const double width = std::stod(svg.substr(svg.find("width=\"") + 7));
  for (std::size_t at = svg.find("fill=\"#555\">"); at != std::string::npos; at = svg.find("fill=\"#555\">", at + 1)) {
    const std::size_t from = at + 13, to = svg.find("</text>", from);
    EXPECT_LE(8.0 + static_cast<double>(to - from) * 7.0 * 10.0 / 11.0, width) << svg.substr(from, to - from);
  }
  // The figure grows by the lines it added.
  const double height = std::stod(svg.substr(svg.find("height=\"") + 8));
  const double short_height = std::stod(one.substr(one.find("height=\"") + 8));
  EXPECT_DOUBLE_EQ(height - short_height, 13.0 * static_cast<double>(lines - 1));
}

TEST(SvgPlot, ManyCategoriesTurnTheirLabelsAndTheLegendGrows) {
  Figure f;
  Panel p{"", "condition", "best", {}, {}, {}, false};
  for (int i = 0; i < 24; ++i) {
    p.categories.push_back("time_constant=" + std::to_string(10 * i) + "ms");
    p.boxes.push_back({"x", 0, static_cast<std::size_t>(i), {1.0 * i, 2.0 * i}});
    f.legend.push_back({"series " + std::to_string(i), static_cast<std::size_t>(i), {}});
  }
  f.panels = {p};
  const std::string svg = render(f);
  EXPECT_EQ(count(svg, "rotate(-35)"), 24u);
  for (int i = 0; i < 24; ++i) EXPECT_NE(svg.find(">series " + std::to_string(i) + "</text>"), std::string::npos);
  const std::size_t h = svg.find("height=\"");
  EXPECT_GE(std::stod(svg.substr(h + 8)), 24 * 16.0);
}

}  // namespace
}  // namespace esc::report::svg
