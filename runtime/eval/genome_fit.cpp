#include "runtime/eval/genome_fit.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "runtime/control/graph_net.hpp"
#include "runtime/genome/tree/codec.hpp"

namespace esc::eval {

std::string genome_problem(const control::ControllerSpec& c, std::span<const double> genome, int roles,
                           std::string_view evolved) {
  if (c.is_graph()) {
    const std::string why = control::graph_genome_problem(c, genome);
    return why.empty() ? why : fmt::format("it is not a genome of `{}`'s NEAT network here: {}", c.name, why);
  }
  if (c.is_tree()) {
    try {
      (void)genome::tree::decode(genome, *c.primitives);
      return {};
    } catch (const std::invalid_argument& e) {
      return fmt::format("it is not a tree of `{}`'s primitives here: {}", c.name, e.what());
    }
  }
  const std::size_t wanted = c.genome_size() * static_cast<std::size_t>(roles);
  if (genome.size() == wanted) return layout_problem(c, evolved);
  if (roles == 1)
    return fmt::format("it has {} genes, `{}` has {} here ({})", genome.size(), c.name, wanted, c.architecture());
  return fmt::format("it has {} genes, `{}` has {} here ({} roles of {}: {})", genome.size(), c.name, wanted, roles,
                     c.genome_size(), c.architecture());
}

namespace {

// Each network's body and architecture, in the genome's order; a controller that is one
// network has one, of no body.
struct Layout {
  std::vector<std::string> bodies, networks;
};
// As stored: "khepera 8-4-2 / thymio2 7-4-2" -> {"khepera", "thymio2"} and {"8-4-2", "7-4-2"};
// "8-4-2" -> {""} and {"8-4-2"}.
Layout layout_of(std::string_view architecture) {
  Layout l;
  for (std::size_t at = 0; at <= architecture.size();) {
    const std::size_t end = std::min(architecture.find(" / ", at), architecture.size());
    const std::string_view part = architecture.substr(at, end - at);
    const std::size_t space = part.rfind(' ');
    l.bodies.emplace_back(space == std::string_view::npos ? std::string_view() : part.substr(0, space));
    l.networks.emplace_back(space == std::string_view::npos ? part : part.substr(space + 1));
    at = end + 3;
  }
  return l;
}
Layout layout_of(const control::ControllerSpec& c) {
  if (!c.per_body()) return {{""}, {c.architecture()}};
  Layout l{c.network_bodies, {}};
  for (const control::ControllerSpec& n : c.networks) l.networks.push_back(n.architecture());
  return l;
}

}  // namespace

std::string layout_problem(const control::ControllerSpec& c, std::string_view evolved) {
  if (evolved.empty() || (!c.per_body() && evolved.find(" / ") == std::string_view::npos)) return {};
  const Layout was = layout_of(evolved), is = layout_of(c);
  // The networks in another order read one body's weights as another's; the same bodies in
  // another order too, even where their networks are alike. Bodies renamed (another robot
  // declaration, `esc replay --script`) keep the genome's order.
  std::vector<std::string> a = was.bodies, b = is.bodies;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const bool reordered = a == b && was.bodies != is.bodies && a.size() > 1;
  if (was.networks == is.networks && !reordered) return {};
  return fmt::format("it was evolved by `{}`, and `{}` here is `{}`: a controller per body's genome holds its "
                     "networks in its declaration's order",
                     evolved, c.name, c.architecture());
}

}  // namespace esc::eval
