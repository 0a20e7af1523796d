#include "runtime/store/tree_state.hpp"

#include <cmath>

#include <fmt/format.h>

#include "runtime/evo/gp/gp_optimizer.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace {

constexpr std::size_t kNodeWidth = 5;   // prim, arity, type, length, value

// A whole number in [0, max] held by a double, or nullopt.
std::optional<std::uint32_t> whole(double v, double max) {
  if (!(v >= 0.0 && v <= max && std::floor(v) == v)) return std::nullopt;
  return static_cast<std::uint32_t>(v);
}

}  // namespace

std::optional<eval::OptimizerState> load_tree_state(sql::Database& db, std::int64_t controller_id, int run,
                                             std::string_view damaged) {
  auto st = db.prepare("SELECT individuals, population FROM tree_state WHERE controller_id = ? AND run = ?");
  st.bind(1, controller_id).bind(2, run);
  if (!st.step()) return std::nullopt;
  auto trees = unpack_trees(st.doubles(1), static_cast<std::size_t>(st.int64(0)));
  if (!trees) throw StoreError(fmt::format("{}: the stored population is unreadable", damaged));
  return eval::OptimizerState{"gp", 1, evo::gp::gp_state(*trees)};
}

std::vector<double> pack_trees(const std::vector<evo::gp::Individual>& population) {
  std::vector<double> v;
  for (const evo::gp::Individual& ind : population) {
    v.push_back(ind.fitness);
    v.push_back(static_cast<double>(ind.tree.size()));
    for (const genome::tree::Node& n : ind.tree.nodes) {
      v.push_back(n.prim);
      v.push_back(n.arity);
      v.push_back(static_cast<double>(genome::tree::index_of(n.type)));
      v.push_back(n.length);
      v.push_back(n.value);
    }
  }
  return v;
}

std::optional<std::vector<evo::gp::Individual>> unpack_trees(const std::vector<double>& blob, std::size_t count) {
  std::vector<evo::gp::Individual> pop;
  pop.reserve(count);
  std::size_t at = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (blob.size() - at < 2) return std::nullopt;
    evo::gp::Individual ind;
    ind.fitness = blob[at];
    const auto nodes = whole(blob[at + 1], static_cast<double>((blob.size() - at - 2) / kNodeWidth));
    if (!nodes) return std::nullopt;
    at += 2;
    ind.tree.nodes.resize(*nodes);
    for (genome::tree::Node& n : ind.tree.nodes) {
      const auto prim = whole(blob[at], 0xFFFF), arity = whole(blob[at + 1], genome::tree::kMaxArity),
                 type = whole(blob[at + 2], genome::tree::kTypeCount - 1), length = whole(blob[at + 3], 1e9);
      if (!prim || !arity || !type || !length) return std::nullopt;
      n.prim = static_cast<genome::tree::PrimitiveId>(*prim);
      n.arity = static_cast<std::uint8_t>(*arity);
      n.type = genome::tree::kAllTypes[*type];
      n.length = *length;
      n.value = blob[at + 4];
      at += kNodeWidth;
    }
    pop.push_back(std::move(ind));
  }
  if (at != blob.size()) return std::nullopt;
  return pop;
}

}  // namespace esc::store
