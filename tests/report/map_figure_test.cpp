// The map figure (archive heatmaps, where a run's evaluations fall): its note wraps within
// the figure's width, as the plots' notes do, and the figure grows by the lines it adds.
#include "runtime/report/map_figure.hpp"

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "tests/report/helpers.hpp"

namespace esc::report {
namespace {

using test::count;

double attribute(const std::string& svg, const std::string& name) {
  return std::stod(svg.substr(svg.find(name + "=\"") + name.size() + 2));
}

MapFigure two_tiles(std::string note) {
  return MapFigure{.title = std::string("t"),
                   .x_title = std::string("x"),
                   .y_title = std::string("y"),
                   .value_title = std::string("fitness"),
                   .note = std::move(note),
                   .x_range = {0.0, 1.0},
                   .y_range = {0.0, 1.0},
                   .tiles = {{0.0, 0.0, 0.5, 0.5, 1.0}, {0.5, 0.5, 1.0, 1.0, 2.0}}};
}

TEST(MapFigure, ALongNoteWrapsWithinTheFigure) {
  const std::string one = render_map(two_tiles("400 of 400 cells filled"));
  EXPECT_EQ(count(one, "fill=\"#555\""), 1u);
  std::string words = "evaluations";
  for (int i = 1; i < 30; ++i) words.append(" evaluations");
  const std::string svg = render_map(two_tiles(words));
  const std::size_t lines = count(svg, "fill=\"#555\"");
  EXPECT_GE(lines, 3u) << "360 characters in a figure about 520 pixels wide";
  EXPECT_EQ(count(svg, "evaluations"), 30u);
  const double width = attribute(svg, "width");
  for (std::size_t at = svg.find("fill=\"#555\">"); at != std::string::npos; at = svg.find("fill=\"#555\">", at + 1)) {
    const std::size_t from = at + 12, to = svg.find("</text>", from);
    EXPECT_LE(8.0 + static_cast<double>(to - from) * 7.0, width) << svg.substr(from, to - from);
  }
  EXPECT_DOUBLE_EQ(attribute(svg, "height") - attribute(one, "height"), 14.0 * static_cast<double>(lines - 1));
  EXPECT_NE(svg.find("</text>\n</svg>\n"), std::string::npos) << "the svg still ends after its last line";
}

}  // namespace
}  // namespace esc::report
