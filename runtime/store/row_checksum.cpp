#include "runtime/store/row_checksum.hpp"

#include <bit>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::store {

namespace {

constexpr std::string_view kColumn = "checksum";

// Index of the column `checksum` in `q`'s rows; -1 when it has none.
int checksum_column(const sql::Statement& q) {
  for (int c = 0; c < q.column_count(); ++c)
    if (q.column_name(c) == kColumn) return c;
  return -1;
}

// Hash of the current row of `q` (every column but `skip`, the checksum): each value as its
// type and its bytes, so that 1 and 1.0, or "" and NULL, differ.
std::uint64_t row_hash(const sql::Statement& q, int skip) {
  std::uint64_t h = content_hash(std::string_view());
  const auto add_u64 = [&h](std::uint64_t v) {
    char b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xffU);
    h = content_hash(std::string_view(b, 8), h);
  };
  for (int c = 0; c < q.column_count(); ++c) {
    if (c == skip) continue;
    const sql::Statement::Type t = q.type(c);
    const char tag = static_cast<char>('0' + static_cast<int>(t));
    h = content_hash(std::string_view(&tag, 1), h);
    switch (t) {
      case sql::Statement::Type::Integer: add_u64(static_cast<std::uint64_t>(q.int64(c))); break;
      case sql::Statement::Type::Real: add_u64(std::bit_cast<std::uint64_t>(q.real(c))); break;
      case sql::Statement::Type::Text:
      case sql::Statement::Type::Blob: {
        const std::string_view b = q.bytes(c);
        add_u64(b.size());
        h = content_hash(b, h);
        break;
      }
      case sql::Statement::Type::Null: break;
    }
  }
  return h;
}

std::optional<std::int64_t> column_value(const sql::Statement& q, std::string_view name) {
  for (int c = 0; c < q.column_count(); ++c)
    if (q.column_name(c) == name && q.type(c) == sql::Statement::Type::Integer) return q.int64(c);
  return std::nullopt;
}

// Every sealed table and what it holds, for the message that refuses a damaged row: one
// list, so a table sealed is a table named.
struct SealedTable {
  std::string_view name;
  std::string_view meaning;
};
constexpr SealedTable kSealedTables[] = {
    {"experiments", "the experiment's record (seed, runs, generations, command-line settings)"},
    {"sources", "a stored source file"},
    {"settings", "a stored setting"},
    {"controllers", "a controller's record"},
    {"runs", "the run's record (seed, best fitness and genome)"},
    {"generations", "the statistics of a generation"},
    {"run_state", "the population to continue from (ES parents and step sizes)"},
    {"tree_state", "the population to continue from (GP trees)"},
    {"optimizer_state", "the optimizer's state to continue from"},
    {"metrics", "the optimizer's metrics of a generation"},   // schemas 6 to 8
    {"metric_names", "the name of an optimizer's metric"},
    {"member_layouts", "what a controller's optimizer keeps beside the best"},
    {"members", "a member of a generation's front or archive changes"},   // schemas 8 and 9
    {"member_generations", "the front or archive changes of a generation"},
    {"behavior_usage", "the behavior usage"},
    {"replays", "the stored replay"},
    {"studies", "the study's record"},
    {"conditions", "a condition's record"},
    {"condition_settings", "a condition's setting"},
    {"generation_usage", "the behavior usage of a generation"},
    {"choices", "a controller's list of behaviors"},
    {"transfers", "a transferred controller's origin fitness"},
};

std::string_view meaning(std::string_view table) {
  for (const SealedTable& t : kSealedTables)
    if (t.name == table) return t.meaning;
  return table;
}

// "run 2 of CS, generation 14" for a row that names them.
std::string row_name(sql::Database& db, const sql::Statement& q) {
  std::string where;
  const auto controller = column_value(q, "controller_id");
  if (const auto run = column_value(q, "run")) where += fmt::format(" of run {}", *run + 1);
  if (controller) {
    std::string name = fmt::format("#{}", *controller);
    try {
      auto n = db.prepare("SELECT name FROM controllers WHERE id = ?");
      n.bind(1, *controller);
      if (n.step()) name = n.text(0);
    } catch (const sql::SqliteError&) {   // the name is only for the message
    }
    where += fmt::format(" of {}", name);
  }
  if (const auto g = column_value(q, "generation")) where += fmt::format(", generation {}", *g);
  return where;
}

}  // namespace

const std::vector<std::string_view>& sealed_tables() {
  static const std::vector<std::string_view> tables = [] {
    std::vector<std::string_view> names;
    for (const SealedTable& t : kSealedTables) names.push_back(t.name);
    return names;
  }();
  return tables;
}

void seal_row(sql::Database& db, std::string_view table, std::int64_t rowid) {
  auto q = db.prepare(fmt::format("SELECT * FROM {} WHERE rowid = ?", table));
  q.bind(1, rowid);
  if (!q.step()) throw StoreError(fmt::format("internal error: no row {} in table {} to seal", rowid, table));
  const auto h = static_cast<std::int64_t>(row_hash(q, checksum_column(q)));
  db.prepare(fmt::format("UPDATE {} SET checksum = ? WHERE rowid = ?", table)).bind(1, h).bind(2, rowid).run();
}

void seal_table(sql::Database& db, std::string_view table) {
  std::vector<std::int64_t> rows;
  auto q = db.prepare(fmt::format("SELECT rowid FROM {}", table));
  while (q.step()) rows.push_back(q.int64(0));
  for (const std::int64_t r : rows) seal_row(db, table, r);
}

void verify_rows(sql::Database& db, const std::filesystem::path& file) {
  for (const std::string_view table : sealed_tables()) {
    // A table that a later schema added is absent from a database read without upgrading it.
    if (!db.has_table(table)) continue;
    auto q = db.prepare(fmt::format("SELECT * FROM {}", table));
    const int sum = checksum_column(q);
    while (q.step()) {
      if (sum >= 0 && q.type(sum) == sql::Statement::Type::Integer &&
          static_cast<std::uint64_t>(q.int64(sum)) == row_hash(q, sum))
        continue;
      throw StoreError(fmt::format("{} is damaged: {}{} does not match its checksum (table {}); it is not used",
                                   file.string(), meaning(table), row_name(db, q), table));
    }
  }
}

}  // namespace esc::store
