#include "runtime/evo/map_elites/descriptor_space.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace esc::evo::qd {

DescriptorSpace::DescriptorSpace(std::vector<Range> ranges) : ranges_(std::move(ranges)) {
  if (ranges_.empty()) throw std::invalid_argument("descriptor ranges: at least one descriptor is needed");
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    const Range& r = ranges_[i];
    if (!std::isfinite(r.upper - r.lower) || !(r.lower < r.upper))
      throw std::invalid_argument("descriptor ranges: descriptor " + std::to_string(i) +
                                  " needs lower < upper, finite and a finite width apart");
  }
}

void DescriptorSpace::to_unit(std::span<const double> descriptor, std::span<double> unit) const {
  if (descriptor.size() != ranges_.size() || unit.size() != ranges_.size())
    throw std::invalid_argument("descriptor: " + std::to_string(descriptor.size()) + " values, the space has " +
                                std::to_string(ranges_.size()));
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    if (!std::isfinite(descriptor[i]))
      throw std::invalid_argument("descriptor: value " + std::to_string(i) + " is not a finite number");
    const Range& r = ranges_[i];
    unit[i] = std::clamp((descriptor[i] - r.lower) / (r.upper - r.lower), 0.0, 1.0);
  }
}

std::vector<double> DescriptorSpace::to_unit(std::span<const double> descriptor) const {
  std::vector<double> unit(ranges_.size());
  to_unit(descriptor, unit);
  return unit;
}

DescriptorSpace descriptor_space_of(std::span<const Bounds> descriptors) {
  std::vector<Range> ranges;
  for (const Bounds& b : descriptors) ranges.push_back({b.lower, b.upper});
  return DescriptorSpace(std::move(ranges));
}

}  // namespace esc::evo::qd
