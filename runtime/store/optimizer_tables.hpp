#pragma once
// What a run's optimizer keeps in the results database (schema 6): its whole state after the
// run's last finished generation (table optimizer_state: the algorithm, the layout of its
// bytes, the bytes, as eval::OptimizerState holds them; its own numbers per generation are
// in metric_tables.hpp). The bytes are stored as they are, so a resumed run is bit-identical
// to the run that was not interrupted.
#include <cstdint>
#include <optional>
#include <string_view>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Since schema 9 a finished run's state is kept compressed (column optimizer_state.raw_size).
inline constexpr int kCompressedStateSchemaVersion = 9;

// Writes (or replaces) the state of run `run` of the controller with id `controller_id`, as
// it is: it is rewritten every generation, and compressing each would cost a few percent of
// a generation's time.
void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::OptimizerState& state);
// Compresses that run's stored state, once it is finished (schema 9): what a finished study
// keeps of each run, read back only to carry the run on.
void compress_state(sql::Database& db, std::int64_t controller_id, int run);
// A finished run's state as compress_state stored it, uncompressed to its `raw_size` bytes;
// nullopt when it does not uncompress to exactly that many.
[[nodiscard]] std::optional<evo::StateBytes> uncompress_state(std::string_view packed, std::int64_t raw_size);
// The state stored for that run by schema 6 or later, uncompressed; nullopt when there is
// none. Throws StoreError, its message starting with `damaged`, for compressed bytes that do
// not uncompress to their size.
[[nodiscard]] std::optional<eval::OptimizerState> load_optimizer_state(sql::Database& db, std::int64_t controller_id,
                                                                       int run, bool has_raw_size,
                                                                       std::string_view damaged);

}  // namespace esc::store
