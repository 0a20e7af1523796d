#include "runtime/genome/graph/mutation.hpp"

#include <algorithm>
#include <vector>

namespace esc::genome::graph {

namespace {

// NEAT C++'s randposneg(): +1 or -1, evenly.
double sign(Rng& rng) { return rng.below(2) == 0 ? 1.0 : -1.0; }

// NEAT C++'s randint(lo, hi), both ends included.
std::size_t pick(Rng& rng, std::size_t lo, std::size_t hi) {
  return lo + static_cast<std::size_t>(rng.below(hi - lo + 1));
}

bool from_bias(const Graph& g, const LinkGene& l) { return g.nodes[node_index(g, l.in)].kind == NodeKind::Bias; }

bool joined(const Graph& g, Id in, Id out) {
  return std::any_of(g.links.begin(), g.links.end(), [&](const LinkGene& l) { return l.in == in && l.out == out; });
}

// Thresholds of NEAT C++'s weight mutation: a draw above `perturb` perturbs, one between
// `replace` and `perturb` replaces.
constexpr double kSeverePerturb = 0.3, kSevereReplace = 0.1;
constexpr double kTailPerturb = 0.5, kTailReplace = 0.3;
constexpr double kTailFrom = 0.8;            // the last 20% of the links...
constexpr double kTailMinLinks = 10.0;       // ...of a genome of at least 10
constexpr std::size_t kSmallGenome = 15;     // add-node favours old links below this
constexpr double kMoveOn = 0.3;
constexpr int kSplitTries = 20;

}  // namespace

void mutate_weights(Graph& g, double power, Rng& rng) {
  const bool severe = rng.uniform() > 0.5;
  const auto total = static_cast<double>(g.links.size());
  double num = 0.0;
  for (LinkGene& l : g.links) {
    double perturb = 0.0, replace = 0.0;
    if (severe) {
      perturb = kSeverePerturb;
      replace = kSevereReplace;
    } else if (total >= kTailMinLinks && num > total * kTailFrom) {
      perturb = kTailPerturb;
      replace = kTailReplace;
    } else if (rng.uniform() > 0.5) {
      replace = -0.1;   // with NEAT's rate 1.0 both thresholds are at or below 0: always perturbed
    }
    const double step = sign(rng) * rng.uniform() * power;
    const double choice = rng.uniform();
    if (choice > perturb) {
      l.weight += step;
    } else if (choice > replace) {
      l.weight = step;
    }
    num += 1.0;
  }
}

void replace_weights(Graph& g, double power, Rng& rng) {
  for (LinkGene& l : g.links) l.weight = sign(rng) * rng.uniform() * power;
}

bool add_node(Graph& g, InnovationRecord& record, Activation activation, Rng& rng) {
  const std::size_t n = g.links.size();
  std::size_t at = n;
  if (n < kSmallGenome) {
    std::size_t i = 0;
    while (i < n && (!g.links[i].enabled || from_bias(g, g.links[i]))) ++i;
    while (i < n && (rng.uniform() < kMoveOn || from_bias(g, g.links[i]))) ++i;
    if (i < n && g.links[i].enabled) at = i;
  } else {
    for (int t = 0; t < kSplitTries && at == n; ++t) {
      const std::size_t i = pick(rng, 0, n - 1);
      if (g.links[i].enabled && !from_bias(g, g.links[i])) at = i;
    }
  }
  if (at == n) return false;
  const LinkGene old = g.links[at];
  const InnovationRecord::Split s = record.split(old.in, old.out, old.innovation);
  if (node_index(g, s.node) != g.nodes.size()) return false;
  g.links[at].enabled = false;
  insert_node(g, {s.node, NodeKind::Hidden, activation});
  insert_link(g, {old.in, s.node, 1.0, true, s.in_innovation});
  insert_link(g, {s.node, old.out, old.weight, true, s.out_innovation});
  return true;
}

bool is_recurrent(const Graph& g, Id in, Id out) {
  if (in == out) return true;
  std::vector<char> seen(g.nodes.size(), 0);
  std::vector<Id> stack{out};
  seen[node_index(g, out)] = 1;
  while (!stack.empty()) {
    const Id at = stack.back();
    stack.pop_back();
    for (const LinkGene& l : g.links) {
      if (!l.enabled || l.in != at) continue;
      if (l.out == in) return true;
      char& s = seen[node_index(g, l.out)];
      if (s == 0) {
        s = 1;
        stack.push_back(l.out);
      }
    }
  }
  return false;
}

bool add_link(Graph& g, InnovationRecord& record, double recur_only_prob, int tries, double new_weight, Rng& rng) {
  const bool recurrent = rng.uniform() < recur_only_prob;
  const std::size_t n = g.nodes.size();
  const std::size_t first = sensor_count(g);
  for (int t = 0; t < tries; ++t) {
    std::size_t i = 0, j = 0;
    if (recurrent && rng.uniform() > 0.5) {
      i = j = pick(rng, first, n - 1);
    } else {
      i = pick(rng, 0, n - 1);
      j = pick(rng, first, n - 1);
    }
    const Id in = g.nodes[i].id, out = g.nodes[j].id;
    if (joined(g, in, out) || is_recurrent(g, in, out) != recurrent) continue;
    LinkGene link{in, out, 0.0, true, 0};
    if (const auto made = record.link(in, out)) {
      link.innovation = made->innovation;
      link.weight = made->weight;
    } else {
      link.weight = sign(rng) * rng.uniform() * new_weight;
      link.innovation = record.add_link(in, out, link.weight);
    }
    insert_link(g, link);
    return true;
  }
  return false;
}

void toggle_enable(Graph& g, Rng& rng) {
  if (g.links.empty()) return;
  LinkGene& l = g.links[pick(rng, 0, g.links.size() - 1)];
  if (!l.enabled) {
    l.enabled = true;
    return;
  }
  const bool other = std::any_of(g.links.begin(), g.links.end(), [&](const LinkGene& o) {
    return o.in == l.in && o.enabled && o.innovation != l.innovation;
  });
  if (other) l.enabled = false;
}

void reenable(Graph& g) {
  const auto it = std::find_if(g.links.begin(), g.links.end(), [](const LinkGene& l) { return !l.enabled; });
  if (it != g.links.end()) it->enabled = true;
}

}  // namespace esc::genome::graph
