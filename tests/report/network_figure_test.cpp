// The drawing of a NEAT network: sensors left, outputs right, a hidden node in the column of
// its depth, one line per enabled link (a disabled one left out, a recurrent one dashed),
// coloured by the weight's sign.
#include "runtime/report/network_figure.hpp"

#include <string>

#include <gtest/gtest.h>

namespace esc::report {
namespace {

namespace gg = genome::graph;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(NetworkFigure, DrawsEveryNodeAndEnabledLinkInColumnsByDepth) {
  // 2 inputs, bias, 1 output (node 4): links 1..3 into it, then 1 split by hidden node 5.
  gg::Graph g = gg::minimal_graph(2, 1, gg::Activation::NeatSigmoid);
  for (gg::LinkGene& l : g.links) l.weight = 0.5;
  g.links[0].enabled = false;
  gg::insert_node(g, {5, gg::NodeKind::Hidden, gg::Activation::NeatSigmoid});
  gg::insert_link(g, {1, 5, 1.0, true, 4});
  gg::insert_link(g, {5, 4, -2.0, true, 5});
  gg::insert_link(g, {4, 5, 0.3, true, 6});   // recurrent: output back to the hidden node
  const std::string svg = network_svg(g, "net <1>");
  EXPECT_EQ(count(svg, "<circle"), 5);
  EXPECT_EQ(count(svg, "<line"), 5);   // 6 links, 1 disabled
  EXPECT_EQ(count(svg, "stroke-dasharray"), 1);
  EXPECT_EQ(count(svg, "#c0392b"), 1);   // the one negative weight
  EXPECT_NE(svg.find("net &lt;1&gt;"), std::string::npos);
  // Columns: sensors at x 70, the hidden node one column right, the output two.
  EXPECT_NE(svg.find("<circle cx=\"70.0\""), std::string::npos);
  EXPECT_NE(svg.find("<circle cx=\"210.0\""), std::string::npos);
  EXPECT_NE(svg.find("<circle cx=\"350.0\""), std::string::npos);
}

}  // namespace
}  // namespace esc::report
