#include "runtime/evo/map_elites/selection.hpp"

#include <stdexcept>

namespace esc::evo::qd {

const Elite& select_uniform(const Archive& archive, Rng& rng) {
  if (archive.filled() == 0) throw std::logic_error("select_uniform: the archive is empty");
  return *archive.elite(archive.filled_cells()[rng.below(archive.filled())]);
}

}  // namespace esc::evo::qd
