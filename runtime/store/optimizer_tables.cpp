#include "runtime/store/optimizer_tables.hpp"

#include <string_view>

#include <fmt/format.h>
#include <zlib.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::OptimizerState& state) {
  db.prepare("INSERT OR REPLACE INTO optimizer_state(controller_id, run, algorithm, format, state) VALUES (?, ?, ?, ?, ?)")
      .bind(1, controller_id).bind(2, run).bind(3, state.algorithm).bind(4, static_cast<std::int64_t>(state.format))
      .bind_blob(5, std::span<const std::uint8_t>(state.bytes))
      .run();
  seal_row(db, "optimizer_state", db.last_insert_rowid());
}

void compress_state(sql::Database& db, std::int64_t controller_id, int run) {
  auto st = db.prepare("SELECT rowid, state FROM optimizer_state WHERE controller_id = ? AND run = ? AND raw_size IS NULL");
  if (!st.bind(1, controller_id).bind(2, run).step()) return;
  const std::int64_t rowid = st.int64(0);
  const std::string_view raw = st.bytes(1);
  uLongf size = compressBound(raw.size());
  evo::StateBytes packed(size);
  // Level 9: once per run, a few tens of milliseconds for NEAT's largest.
  if (compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(raw.data()), raw.size(), 9) != Z_OK)
    throw StoreError("internal error: zlib could not compress a run's state");
  packed.resize(size);
  const auto raw_size = static_cast<std::int64_t>(raw.size());
  st.reset();
  db.prepare("UPDATE optimizer_state SET state = ?, raw_size = ? WHERE rowid = ?")
      .bind_blob(1, std::span<const std::uint8_t>(packed)).bind(2, raw_size).bind(3, rowid)
      .run();
  seal_row(db, "optimizer_state", rowid);
}

std::optional<evo::StateBytes> uncompress_state(std::string_view packed, std::int64_t raw_size) {
  if (raw_size < 0) return std::nullopt;
  uLongf size = static_cast<uLongf>(raw_size);
  evo::StateBytes bytes(size);
  if (uncompress(bytes.data(), &size, reinterpret_cast<const Bytef*>(packed.data()), packed.size()) != Z_OK ||
      size != static_cast<uLongf>(raw_size))
    return std::nullopt;
  return bytes;
}

std::optional<eval::OptimizerState> load_optimizer_state(sql::Database& db, std::int64_t controller_id, int run,
                                                         bool has_raw_size, std::string_view damaged) {
  auto st = db.prepare(fmt::format("SELECT algorithm, format, state, {} FROM optimizer_state "
                                   "WHERE controller_id = ? AND run = ?",
                                   has_raw_size ? "raw_size" : "NULL"));
  st.bind(1, controller_id).bind(2, run);
  if (!st.step()) return std::nullopt;
  const std::string_view bytes = st.bytes(2);
  eval::OptimizerState s{st.text(0), static_cast<std::uint32_t>(st.int64(1)), {}};
  if (st.is_null(3)) {
    s.bytes.assign(bytes.begin(), bytes.end());
    return s;
  }
  const std::int64_t raw_size = st.int64(3);
  std::optional<evo::StateBytes> raw = uncompress_state(bytes, raw_size);
  if (!raw) throw StoreError(fmt::format("{}: its stored state does not uncompress to its {} bytes", damaged, raw_size));
  s.bytes = std::move(*raw);
  return s;
}

}  // namespace esc::store
