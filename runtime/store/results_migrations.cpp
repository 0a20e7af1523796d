// Bringing a database an older esc wrote up to kSchemaVersion when it is opened for
// writing (ResultsDb::upgrade), and the columns an older schema lacks.
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "runtime/store/analysis_tables.hpp"
#include "runtime/store/member_tables.hpp"
#include "runtime/store/metric_tables.hpp"
#include "runtime/store/optimizer_tables.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/results_schema.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

bool ResultsDb::column_exists(const std::string& table, const std::string& column) {
  auto info = db_.prepare(fmt::format("PRAGMA table_info({})", table));
  while (info.step())
    if (info.text(1) == column) return true;
  return false;
}

void ResultsDb::upgrade() {
  // Each step adds what its version needs; what is stored is untouched.
  sql::Transaction tx(db_);
  const std::string schema = results_schema();
  const auto tables = [&](const char* first, const char* end) {
    const std::size_t a = schema.find(first);
    db_.exec(schema.substr(a, end == nullptr ? std::string::npos : schema.find(end) - a));
  };
  if (schema_version_ < 2) {   // GP
    db_.exec("ALTER TABLE runs ADD COLUMN best_behavior TEXT;");
    tables("CREATE TABLE tree_state", "CREATE TABLE behavior_usage");
  }
  if (schema_version_ < 3) tables("CREATE TABLE studies", nullptr);   // studies
  // The analyses' tables, empty: the generations stored before have no usage.
  if (schema_version_ < kAnalysisSchemaVersion) db_.exec(analysis_schema());
  if (schema_version_ < 6) tables("CREATE TABLE optimizer_state", "CREATE TABLE studies");   // optimizers
  if (schema_version_ < 7) {   // each controller's algorithm, a run's early stop
    db_.exec("ALTER TABLE controllers ADD COLUMN algorithm TEXT; ALTER TABLE runs ADD COLUMN stopped TEXT;");
    if (schema_version_ == 6)   // the algorithm that saved each controller's run states
      db_.exec("UPDATE controllers SET algorithm = (SELECT s.algorithm FROM optimizer_state s "
               "WHERE s.controller_id = controllers.id LIMIT 1);");
    // Their rows' checksums covered the columns they had (an older schema's are sealed below).
    if (schema_version_ >= 5) {
      seal_table(db_, "controllers");
      seal_table(db_, "runs");
    }
  }
  if (schema_version_ < kMemberSchemaVersion) {   // 8: a run's first successful evaluation, members
    db_.exec("ALTER TABLE runs ADD COLUMN success_evaluation INTEGER;");
    if (schema_version_ >= 5) seal_table(db_, "runs");   // the rows now hold one more column
    db_.exec(member_schema());
  }
  if (schema_version_ < kMetricSchemaVersion) {   // 9: metrics in their generation's row, states compressed
    move_metrics_into_generations(db_, schema_version_ >= 6);
    if (schema_version_ >= 5) seal_table(db_, "generations");   // the rows now hold two more columns
    if (schema_version_ >= 6) {   // older ones got the table as this schema has it above
      db_.exec("ALTER TABLE optimizer_state ADD COLUMN raw_size INTEGER;");
      seal_table(db_, "optimizer_state");
    }
  }
  // 10: a row per generation of members (older than 8: created with member_layouts above)
  if (schema_version_ >= kMemberSchemaVersion && schema_version_ < kPackedMemberSchemaVersion) pack_member_rows(db_);
  if (schema_version_ < 5) {   // saturated evaluations, checksums (the analyses' tables too)
    if (!column_exists("generations", "saturated"))
      db_.exec("ALTER TABLE generations ADD COLUMN saturated INTEGER NOT NULL DEFAULT 0;");
    for (const std::string_view t : sealed_tables()) {
      if (!db_.has_table(t)) continue;   // one a later schema dropped (metrics, 9)
      if (!column_exists(std::string(t), "checksum"))
        db_.exec(fmt::format("ALTER TABLE {} ADD COLUMN checksum INTEGER NOT NULL DEFAULT 0;", t));
      seal_table(db_, t);
    }
  }
  db_.exec(fmt::format("PRAGMA user_version={};", kSchemaVersion));
  tx.commit();
  schema_version_ = kSchemaVersion;
}

}  // namespace esc::store
