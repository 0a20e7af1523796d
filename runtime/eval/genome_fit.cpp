#include "runtime/eval/genome_fit.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "runtime/control/graph_net.hpp"
#include "runtime/genome/tree/codec.hpp"

namespace esc::eval {

std::string genome_problem(const control::ControllerSpec& c, std::span<const double> genome, int roles) {
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
  if (genome.size() == wanted) return {};
  if (roles == 1)
    return fmt::format("it has {} genes, `{}` has {} here ({})", genome.size(), c.name, wanted, c.architecture());
  return fmt::format("it has {} genes, `{}` has {} here ({} roles of {}: {})", genome.size(), c.name, wanted, roles,
                     c.genome_size(), c.architecture());
}

std::string layout_problem(const control::ControllerSpec& c, const std::string& evolved) {
  const std::string here = c.architecture();
  const bool per_body = c.per_body() || evolved.find(" / ") != std::string::npos;
  if (!per_body || evolved.empty() || evolved == here) return {};
  return fmt::format("it was evolved by a controller of networks {}, and `{}` here is {}: a controller per body's "
                     "genome holds its networks in its declaration's order",
                     evolved, c.name, here);
}

}  // namespace esc::eval
