#pragma once
// The structural mutations made in one generation (NEAT C++'s innovation list,
// innovation.cpp): the same new link, or the same split of the same link, made twice in one
// generation gets the same innovation numbers (and a split the same new node id and a new
// link the same weight, as NEAT C++ does), so that identical structure lines up in
// crossover. The record is cleared between generations (Population::epoch deletes the
// list); the two counters run on across the whole run and are part of an optimizer's state.
#include <optional>
#include <vector>

#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

class InnovationRecord {
 public:
  InnovationRecord(Id next_innovation, Id next_node) : next_innovation_(next_innovation), next_node_(next_node) {}

  struct Split {
    Id node = 0;                // the new hidden node
    Id in_innovation = 0;       // in -> node
    Id out_innovation = 0;      // node -> out
  };
  // The numbers for splitting link `old_innovation` (in -> out): those of this generation's
  // earlier identical split, else new ones.
  [[nodiscard]] Split split(Id in, Id out, Id old_innovation);

  struct Link {
    Id innovation = 0;
    double weight = 0.0;
  };
  // This generation's earlier new link in -> out, if any.
  [[nodiscard]] std::optional<Link> link(Id in, Id out) const;
  // Records a new link in -> out with its weight; returns its innovation.
  Id add_link(Id in, Id out, double weight);

  // Forgets this generation's mutations; the counters go on.
  void next_generation();

  [[nodiscard]] Id next_innovation() const noexcept { return next_innovation_; }
  [[nodiscard]] Id next_node() const noexcept { return next_node_; }

 private:
  struct SplitMade {
    Id in, out, old_innovation;
    Split numbers;
  };
  struct LinkMade {
    Id in, out;
    Link numbers;
  };
  std::vector<SplitMade> splits_;
  std::vector<LinkMade> links_;
  Id next_innovation_;
  Id next_node_;
};

}  // namespace esc::genome::graph
