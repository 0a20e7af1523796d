#pragma once
// NEAT's mutations of one genome, as NEAT C++'s genome.cpp makes them (the paper leaves
// these details out): the weight mutation, add-node (a link split in two), add-link
// (forward, or recurrent when asked), toggling a link on or off, and re-enabling one.
// Every draw comes from the caller's generator, in an order fixed by the genome alone.
#include <cstddef>

#include "runtime/core/rng.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/innovation.hpp"

namespace esc::genome::graph {

// NEAT C++'s mutate_link_weights(power, 1.0, GAUSSIAN): half the time ("severe") each link
// is perturbed with probability 0.7 and replaced with 0.2; otherwise the last 20% of a
// genome of 10 links or more are perturbed with 0.5 and replaced with 0.2, and every other
// link is perturbed. A perturbation adds, a replacement sets, a number uniform in
// [-power, power]. No cap on the weights (NEAT C++ 1.x has none; later forks cap at 3 to 8).
void mutate_weights(Graph& g, double power, Rng& rng);

// Every weight drawn anew, uniform in [-power, power] (NEAT C++'s COLDGAUSSIAN, with which
// Population::spawn randomises the start genome's copies).
void replace_weights(Graph& g, double power, Rng& rng);

// Splits an enabled link whose input is not the bias: the link is disabled, a hidden node
// (`activation`) takes its place, the link into it weighs 1 and the link out of it the old
// weight (the paper, section 3.1). In a genome of fewer than 15 links the split favours old
// links (from the first eligible one, moving on with probability 0.3 each), otherwise 20
// uniform tries, as NEAT C++. False when none was found.
bool add_node(Graph& g, InnovationRecord& record, Activation activation, Rng& rng);

// Adds a link between two unconnected nodes, its weight uniform in
// [-new_weight, new_weight]: with probability `recur_only_prob` a recurrent one (a link
// whose output already reaches its input, half the time a node's loop on itself), else a
// forward one; up to `tries` draws of a pair, the output never a sensor. A pair already
// joined (enabled or not) is a failed try. False when none was found.
bool add_link(Graph& g, InnovationRecord& record, double recur_only_prob, int tries, double new_weight, Rng& rng);

// A uniformly chosen link is switched: on when off; off when on, unless it is the only
// enabled link out of its input node (which would cut that node off).
void toggle_enable(Graph& g, Rng& rng);

// The first disabled link, in innovation order, is enabled again.
void reenable(Graph& g);

// Whether a link in -> out would be recurrent: out already reaches in through enabled
// links, or in == out.
[[nodiscard]] bool is_recurrent(const Graph& g, Id in, Id out);

}  // namespace esc::genome::graph
