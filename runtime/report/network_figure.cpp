#include "runtime/report/network_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "runtime/control/graph_architecture.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/report/markup.hpp"

namespace esc::report {

namespace gg = genome::graph;

namespace {

constexpr double kColumnGap = 140.0;
constexpr double kRowGap = 36.0;
constexpr double kMargin = 40.0;
constexpr double kTitleHeight = 30.0;
constexpr double kRadius = 9.0;

bool sensor(const gg::NodeGene& n) { return n.kind == gg::NodeKind::Input || n.kind == gg::NodeKind::Bias; }

// Each node's column: sensors 0, hidden nodes their depth over enabled links (relaxed at most
// once per node, so a cycle cannot run on), outputs one right of the deepest hidden node.
std::vector<int> columns(const gg::Graph& g) {
  std::vector<int> col(g.nodes.size(), 0);
  for (std::size_t pass = 0; pass < g.nodes.size(); ++pass) {
    bool changed = false;
    for (const gg::LinkGene& l : g.links) {
      const std::size_t in = gg::node_index(g, l.in), out = gg::node_index(g, l.out);
      if (!l.enabled || in == out || g.nodes[out].kind == gg::NodeKind::Output) continue;
      if (col[out] < col[in] + 1 && col[in] + 1 <= static_cast<int>(g.nodes.size())) {
        col[out] = col[in] + 1;
        changed = true;
      }
    }
    if (!changed) break;
  }
  int deepest = 0;
  for (std::size_t k = 0; k < g.nodes.size(); ++k)
    if (g.nodes[k].kind == gg::NodeKind::Hidden) deepest = std::max(deepest, col[k]);
  for (std::size_t k = 0; k < g.nodes.size(); ++k)
    if (g.nodes[k].kind == gg::NodeKind::Output) col[k] = deepest + 1;
  return col;
}

}  // namespace

std::string network_svg(const gg::Graph& g, const std::string& title) {
  const std::vector<int> col = columns(g);
  const int last = col.empty() ? 0 : *std::max_element(col.begin(), col.end());
  std::vector<int> row(g.nodes.size(), 0);
  std::vector<int> filled(static_cast<std::size_t>(last) + 1, 0);
  for (std::size_t k = 0; k < g.nodes.size(); ++k) row[k] = filled[static_cast<std::size_t>(col[k])]++;
  const int rows = *std::max_element(filled.begin(), filled.end());
  const double width = 2.0 * kMargin + kColumnGap * last + 60.0;
  const double height = kTitleHeight + 2.0 * kMargin + kRowGap * std::max(rows - 1, 0);
  const auto x = [&](std::size_t k) { return kMargin + 30.0 + kColumnGap * col[k]; };
  // Each column centred vertically.
  const auto y = [&](std::size_t k) {
    const int n = filled[static_cast<std::size_t>(col[k])];
    return kTitleHeight + kMargin + kRowGap * (row[k] + 0.5 * (rows - n));
  };
  double heaviest = 0.0;
  for (const gg::LinkGene& l : g.links)
    if (l.enabled) heaviest = std::max(heaviest, std::abs(l.weight));
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{:.0f}\" y=\"20\" font-size=\"14\">{}</text>\n",
      width, height, width, height, kMargin, escape_markup(title));
  for (const gg::LinkGene& l : g.links) {
    if (!l.enabled) continue;
    const std::size_t in = gg::node_index(g, l.in), out = gg::node_index(g, l.out);
    const double w = heaviest > 0.0 ? 0.5 + 3.5 * std::abs(l.weight) / heaviest : 1.0;
    const bool back = col[out] <= col[in];
    svg += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"{:.2f}\" "
        "stroke-opacity=\"0.7\"{}><title>{} -> {} weight {:.4g} (innovation {})</title></line>\n",
        x(in), y(in), x(out), y(out), l.weight >= 0.0 ? "#1f5fbf" : "#c0392b", w,
        back ? " stroke-dasharray=\"4 3\"" : "", l.in, l.out, l.weight, l.innovation);
  }
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    const gg::NodeGene& n = g.nodes[k];
    const char* fill = sensor(n) ? "#dddddd" : n.kind == gg::NodeKind::Output ? "#f3c969" : "#9fd3a8";
    const std::string label = n.kind == gg::NodeKind::Bias ? std::string("bias") : fmt::format("{}", n.id);
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.0f}\" fill=\"{}\" stroke=\"black\"><title>node {} {}{}</title>"
        "</circle>\n<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"{}\">{}</text>\n",
        x(k), y(k), kRadius, fill, n.id, gg::kind_name(n.kind),
        sensor(n) ? std::string() : std::string(" ") + std::string(gg::activation_name(n.activation)),
        sensor(n) ? x(k) - kRadius - 4.0 : x(k) + kRadius + 4.0, y(k) + 4.0, sensor(n) ? "end" : "start", label);
  }
  svg += "</svg>\n";
  return svg;
}

std::vector<NamedFigure> network_figures(const store::StoredExperiment& e, const std::string& stem) {
  std::vector<NamedFigure> out;
  for (const store::StoredController& c : e.controllers) {
    if (!control::is_graph_architecture(c.architecture)) continue;
    for (std::size_t r = 0; r < c.finished.size(); ++r) {
      gg::Graph g;
      if (!gg::decode(c.finished[r].best_genome, g).empty()) continue;
      const std::string title = fmt::format("{} run {}: best network, {} hidden nodes, {} enabled links (fitness {:.4g})",
                                            c.name, r + 1, gg::count_nodes(g, gg::NodeKind::Hidden),
                                            gg::enabled_links(g), c.finished[r].best_fitness);
      out.push_back({fmt::format("{}-network-{}-run-{:02}.svg", stem, c.name, r + 1), title, network_svg(g, title)});
    }
  }
  return out;
}

}  // namespace esc::report
