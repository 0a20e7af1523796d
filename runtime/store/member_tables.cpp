#include "runtime/store/member_tables.hpp"

#include <algorithm>
#include <cstring>
#include <map>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

using nlohmann::json;

const char* member_kind_name(evo::MemberKind kind) { return kind == evo::MemberKind::Front ? "front" : "archive"; }

const char* member_schema() {
  return R"sql(
CREATE TABLE member_layouts (
  controller_id INTEGER PRIMARY KEY REFERENCES controllers(id),
  kind          TEXT NOT NULL,     -- front | archive
  objectives    TEXT NOT NULL,     -- JSON: [{"name", "minimize"}], the fitness first
  descriptors   TEXT NOT NULL,     -- JSON: [{"name", "lower", "upper"}]
  bins          TEXT NOT NULL,     -- JSON: a grid archive's bins per descriptor, else []
  centroids     BLOB NOT NULL,     -- a CVT archive's centroids (unit coordinates), else empty
  checksum      INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE members (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  idx           INTEGER NOT NULL,
  cell          INTEGER NOT NULL,  -- an archive's cell; a front's position
  objectives    BLOB NOT NULL,     -- doubles, as measured
  descriptors   BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation, idx)
);
)sql";
}

namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Whether the run's last stored front holds `members` exactly (cells and the values' bits).
bool repeats_last_front(sql::Database& db, std::int64_t controller_id, const eval::RunState& state) {
  auto q = db.prepare("SELECT cell, objectives, descriptors FROM members WHERE controller_id = ?1 AND run = ?2 AND "
                      "generation = (SELECT MAX(generation) FROM members WHERE controller_id = ?1 AND run = ?2) "
                      "ORDER BY idx");
  q.bind(1, controller_id).bind(2, state.run);
  std::size_t i = 0;
  for (; q.step(); ++i) {
    if (i == state.members.size()) return false;
    const evo::Member& m = state.members[i];
    if (q.int64(0) != m.cell || !same_bits(q.doubles(1), m.objectives) || !same_bits(q.doubles(2), m.descriptors))
      return false;
  }
  return i > 0 && i == state.members.size();
}

}  // namespace

void save_members(sql::Database& db, std::int64_t controller_id, const eval::RunState& state, int generation) {
  if (!state.members_due) return;
  const eval::MemberLayout& layout = *state.member_layout;
  auto exists = db.prepare("SELECT 1 FROM member_layouts WHERE controller_id = ?");
  if (!exists.bind(1, controller_id).step()) {
    json objectives = json::array(), descriptors = json::array();
    for (std::size_t i = 0; i < layout.objectives.size(); ++i)
      objectives.push_back({{"name", layout.objectives[i]}, {"minimize", static_cast<bool>(layout.minimized[i])}});
    for (std::size_t i = 0; i < layout.descriptors.size(); ++i)
      descriptors.push_back({{"name", layout.descriptors[i]},
                             {"lower", layout.descriptor_ranges[i].lower},
                             {"upper", layout.descriptor_ranges[i].upper}});
    db.prepare("INSERT INTO member_layouts(controller_id, kind, objectives, descriptors, bins, centroids) "
               "VALUES (?, ?, ?, ?, ?, ?)")
        .bind(1, controller_id).bind(2, member_kind_name(layout.kind)).bind(3, objectives.dump()).bind(4, descriptors.dump())
        .bind(5, json(layout.bins).dump()).bind_blob(6, std::span<const double>(layout.centroids))
        .run();
    seal_row(db, "member_layouts", db.last_insert_rowid());
  }
  if (layout.kind == evo::MemberKind::Front && repeats_last_front(db, controller_id, state)) return;
  auto row = db.prepare("INSERT INTO members(controller_id, run, generation, idx, cell, objectives, descriptors) "
                        "VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < state.members.size(); ++i) {
    const evo::Member& m = state.members[i];
    row.bind(1, controller_id).bind(2, state.run).bind(3, generation).bind(4, static_cast<std::int64_t>(i))
        .bind(5, m.cell).bind_blob(6, std::span<const double>(m.objectives))
        .bind_blob(7, std::span<const double>(m.descriptors))
        .run();
    seal_row(db, "members", db.last_insert_rowid());
  }
}

std::optional<StoredMembers> load_members(sql::Database& db, std::int64_t controller_id) {
  auto q = db.prepare("SELECT kind, objectives, descriptors, bins, centroids FROM member_layouts "
                      "WHERE controller_id = ?");
  if (!q.bind(1, controller_id).step()) return std::nullopt;
  StoredMembers s;
  eval::MemberLayout& l = s.layout;
  l.kind = q.text(0) == member_kind_name(evo::MemberKind::Front) ? evo::MemberKind::Front : evo::MemberKind::Archive;
  for (const json& o : json::parse(q.text(1))) {
    l.objectives.push_back(o.at("name").get<std::string>());
    l.minimized.push_back(o.at("minimize").get<bool>());
  }
  for (const json& d : json::parse(q.text(2))) {
    l.descriptors.push_back(d.at("name").get<std::string>());
    l.descriptor_ranges.push_back({d.at("lower").get<double>(), d.at("upper").get<double>()});
  }
  l.bins = json::parse(q.text(3)).get<std::vector<std::size_t>>();
  l.centroids = q.doubles(4);
  auto rows = db.prepare("SELECT run, generation, cell, objectives, descriptors FROM members WHERE controller_id = ? "
                         "ORDER BY run, generation, idx");
  rows.bind(1, controller_id);
  while (rows.step())
    s.rows.push_back({rows.integer(0), rows.integer(1), rows.int64(2), rows.doubles(3), rows.doubles(4)});
  return s;
}

std::vector<StoredMember> members_at(const StoredMembers& members, int run, int generation) {
  std::vector<StoredMember> out;
  if (members.layout.kind == evo::MemberKind::Front) {
    int stored = -1;   // the last generation up to `generation` that stored the front
    for (const StoredMember& m : members.rows)
      if (m.run == run && m.generation <= generation) stored = std::max(stored, m.generation);
    for (const StoredMember& m : members.rows)
      if (m.run == run && m.generation == stored) out.push_back(m);
    return out;
  }
  std::map<std::int64_t, const StoredMember*> cells;
  for (const StoredMember& m : members.rows)
    if (m.run == run && m.generation <= generation) cells[m.cell] = &m;
  for (const auto& [cell, m] : cells) out.push_back(*m);
  return out;
}

}  // namespace esc::store
