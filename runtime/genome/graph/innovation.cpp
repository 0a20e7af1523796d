#include "runtime/genome/graph/innovation.hpp"

namespace esc::genome::graph {

InnovationRecord::Split InnovationRecord::split(Id in, Id out, Id old_innovation) {
  for (const SplitMade& s : splits_)
    if (s.in == in && s.out == out && s.old_innovation == old_innovation) return s.numbers;
  const Split made{next_node_++, next_innovation_, next_innovation_ + 1};
  next_innovation_ += 2;
  splits_.push_back({in, out, old_innovation, made});
  return made;
}

std::optional<InnovationRecord::Link> InnovationRecord::link(Id in, Id out) const {
  for (const LinkMade& l : links_)
    if (l.in == in && l.out == out) return l.numbers;
  return std::nullopt;
}

Id InnovationRecord::add_link(Id in, Id out, double weight) {
  links_.push_back({in, out, {next_innovation_, weight}});
  return next_innovation_++;
}

void InnovationRecord::next_generation() {
  splits_.clear();
  links_.clear();
}

}  // namespace esc::genome::graph
