#include "runtime/store/topology_export.hpp"

#include <functional>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "runtime/control/graph_architecture.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/store/export.hpp"

namespace esc::store {

namespace {

namespace gg = genome::graph;

struct TopologyRow {
  const std::string& experiment;
  const std::string& condition;   // empty for a plain experiment
  const std::string& controller;
  int run;                        // from 1
  std::string_view member;        // best, front or archive
  std::optional<std::int64_t> cell;   // a member's
  const gg::NodeGene* node;       // one of the two
  const gg::LinkGene* link;
};

// Every row: the bests in directory, experiment, controller and run order, then the
// members; a genome that does not decode (a store from before graphs could not hold one)
// gives none.
void for_each_row(const std::vector<StoredDirectory>& directories, const std::vector<RunMembers>& members,
                  const std::function<void(const TopologyRow&)>& f) {
  const auto rows_of = [&](const std::vector<double>& genome, const std::string& experiment, const std::string& condition,
                           const std::string& controller, int run, std::string_view member,
                           std::optional<std::int64_t> cell) {
    gg::Graph g;
    if (!gg::decode(genome, g).empty()) return;
    for (const gg::NodeGene& n : g.nodes) f({experiment, condition, controller, run, member, cell, &n, nullptr});
    for (const gg::LinkGene& l : g.links) f({experiment, condition, controller, run, member, cell, nullptr, &l});
  };
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments) {
      const std::string condition = e.condition ? e.condition->name : std::string();
      for (const StoredController& c : e.controllers) {
        if (!control::is_graph_architecture(c.architecture)) continue;
        for (std::size_t r = 0; r < c.finished.size(); ++r)
          rows_of(c.finished[r].best_genome, e.name, condition, c.name, static_cast<int>(r) + 1, "best", std::nullopt);
      }
    }
  for (const RunMembers& m : members)
    for (const auto& [cell, genome] : m.genomes)
      rows_of(genome, m.experiment, m.condition, m.controller, m.run, m.kind, cell);
}

}  // namespace

std::string topology_csv(const std::vector<StoredDirectory>& directories, const std::vector<RunMembers>& members) {
  std::string out = std::string(kTopologyColumns) + "\n";
  for_each_row(directories, members, [&](const TopologyRow& r) {
    out += fmt::format("{},{},{},{},{},{},", r.experiment, csv_field(r.condition), r.controller, r.run, r.member,
                       r.cell ? std::to_string(*r.cell) : std::string());
    if (r.node != nullptr)
      out += fmt::format("node,{},{},{},,,,\n", r.node->id, gg::kind_name(r.node->kind),
                         r.node->kind == gg::NodeKind::Input || r.node->kind == gg::NodeKind::Bias
                             ? std::string_view()
                             : gg::activation_name(r.node->activation));
    else
      out += fmt::format("link,{},,,{},{},{:.17g},{}\n", r.link->innovation, r.link->in, r.link->out, r.link->weight,
                         r.link->enabled ? 1 : 0);
  });
  return out;
}

nlohmann::ordered_json topology_json(const std::vector<StoredDirectory>& directories,
                                     const std::vector<RunMembers>& members) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for_each_row(directories, members, [&](const TopologyRow& r) {
    nlohmann::ordered_json row = {{"experiment", r.experiment}, {"condition", r.condition}, {"controller", r.controller},
                                  {"run", r.run}, {"member", r.member}};
    row["cell"] = r.cell ? nlohmann::ordered_json(*r.cell) : nlohmann::ordered_json();
    const bool sensor = r.node != nullptr && (r.node->kind == gg::NodeKind::Input || r.node->kind == gg::NodeKind::Bias);
    row["element"] = r.node != nullptr ? "node" : "link";
    row["id"] = r.node != nullptr ? r.node->id : r.link->innovation;
    row["kind"] = r.node != nullptr ? nlohmann::ordered_json(gg::kind_name(r.node->kind)) : nlohmann::ordered_json();
    row["activation"] = r.node != nullptr && !sensor ? nlohmann::ordered_json(gg::activation_name(r.node->activation))
                                                     : nlohmann::ordered_json();
    row["in"] = r.link != nullptr ? nlohmann::ordered_json(r.link->in) : nlohmann::ordered_json();
    row["out"] = r.link != nullptr ? nlohmann::ordered_json(r.link->out) : nlohmann::ordered_json();
    row["weight"] = r.link != nullptr ? nlohmann::ordered_json(r.link->weight) : nlohmann::ordered_json();
    row["enabled"] = r.link != nullptr ? nlohmann::ordered_json(r.link->enabled ? 1 : 0) : nlohmann::ordered_json();
    rows.push_back(std::move(row));
  });
  return rows;
}

}  // namespace esc::store
