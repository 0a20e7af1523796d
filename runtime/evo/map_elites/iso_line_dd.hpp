#pragma once
// The Iso+LineDD variation of Vassiliades & Mouret, "Discovering the elite hypervolume by
// leveraging interspecies correlation" (GECCO 2018): from two elites x and y,
//
//   child = x + sigma_iso * N(0, I) + sigma_line * N(0, 1) * (y - x)
//
// an isotropic Gaussian step plus a step along the line through both parents, whose length
// follows their distance: elites share much of their genome (the "elite hypervolume"), so
// the direction from one to another is a good direction to search. One N(0, 1) for the
// whole line term. Here sigma_iso is absolute (MapElites scales its setting by the box
// width), sigma_line is a fraction of the parents' distance, and the child is clipped to
// [lower, upper] in each coordinate, as pymap_elites' iso_dd does.
//
// Draws: x.size() normals for the isotropic term, coordinate by coordinate, then one for
// the line.
#include <span>

#include "runtime/core/rng.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::evo::qd {

struct IsoLineDd {
  double sigma_iso = 0.01;
  double sigma_line = 0.2;
  double lower = -1.0;
  double upper = 1.0;
};

// Throws std::invalid_argument for parents of different sizes.
[[nodiscard]] Genome iso_line_dd(std::span<const double> x, std::span<const double> y, const IsoLineDd& op, Rng& rng);

}  // namespace esc::evo::qd
