#pragma once
// The space a behavior descriptor lives in: one declared range [lower, upper] per
// descriptor. Archives and the novelty archive measure descriptors in this space mapped
// onto the unit cube, each descriptor scaled by its own range, so that descriptors in
// different units (metres, a fraction of time, a count) weigh alike in a distance and
// a CVT or a kd-tree sees one scale.
//
// A value outside its range counts as the nearest bound: a grid puts it in the edge bin, a
// CVT in the cell nearest that bound, the novelty archive at the bound. The run declares
// ranges that hold every behavior it can produce, so clamping only absorbs what a loose
// declaration missed; it never throws away an evaluation.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/evo/optimizer.hpp"

namespace esc::evo::qd {

struct Range {
  double lower = 0.0;
  double upper = 1.0;
  friend bool operator==(const Range&, const Range&) = default;
};

class DescriptorSpace {
 public:
  // Throws std::invalid_argument ("descriptor ranges: ...") for no range, a bound that is
  // not finite, or lower >= upper.
  explicit DescriptorSpace(std::vector<Range> ranges);

  [[nodiscard]] std::size_t size() const noexcept { return ranges_.size(); }
  [[nodiscard]] const std::vector<Range>& ranges() const noexcept { return ranges_; }

  // (d - lower) / (upper - lower) per descriptor, clamped to [0, 1], into `unit` (the size of
  // the space). Throws std::invalid_argument for another count or a value that is not finite.
  void to_unit(std::span<const double> descriptor, std::span<double> unit) const;
  [[nodiscard]] std::vector<double> to_unit(std::span<const double> descriptor) const;

  friend bool operator==(const DescriptorSpace&, const DescriptorSpace&) = default;

 private:
  std::vector<Range> ranges_;
};

// The space of a problem's declared descriptors (throws as the constructor does).
[[nodiscard]] DescriptorSpace descriptor_space_of(std::span<const Bounds> descriptors);

}  // namespace esc::evo::qd
