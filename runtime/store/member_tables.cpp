#include "runtime/store/member_tables.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

using nlohmann::json;

const char* member_kind_name(evo::MemberKind kind) { return kind == evo::MemberKind::Front ? "front" : "archive"; }

namespace {

constexpr const char* kMemberLayouts = R"sql(
CREATE TABLE member_layouts (
  controller_id INTEGER PRIMARY KEY REFERENCES controllers(id),
  kind          TEXT NOT NULL,     -- front | archive
  objectives    TEXT NOT NULL,     -- JSON: [{"name", "minimize"}], the fitness first
  descriptors   TEXT NOT NULL,     -- JSON: [{"name", "lower", "upper"}]
  bins          TEXT NOT NULL,     -- JSON: a grid archive's bins per descriptor, else []
  centroids     BLOB NOT NULL,     -- a CVT archive's centroids (unit coordinates), else empty
  checksum      INTEGER NOT NULL DEFAULT 0
);
)sql";

// Schema 10: one row per generation that stores members (schemas 8 and 9: a row per member in
// table members, 75 bytes each with its key and index; a front of 54 two-objective members
// takes 2.2 KB here against 4.1 KB).
constexpr const char* kMemberGenerations = R"sql(
CREATE TABLE member_generations (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  members       INTEGER NOT NULL,  -- how many: each BLOB holds this many members' values
  cells         BLOB NOT NULL,     -- 64-bit integers: an archive's cell; a front's position
  objectives    BLOB NOT NULL,     -- doubles, as measured, member after member
  descriptors   BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation)
);
)sql";

}  // namespace

std::string member_schema() { return std::string(kMemberLayouts) + kMemberGenerations; }

namespace {

// One generation's members as a row holds them: each member's values in one run of doubles.
struct PackedMembers {
  std::vector<std::int64_t> cells;
  std::vector<double> objectives;
  std::vector<double> descriptors;
};

PackedMembers pack(const std::vector<evo::Member>& members) {
  PackedMembers p;
  for (const evo::Member& m : members) {
    p.cells.push_back(m.cell);
    p.objectives.insert(p.objectives.end(), m.objectives.begin(), m.objectives.end());
    p.descriptors.insert(p.descriptors.end(), m.descriptors.begin(), m.descriptors.end());
  }
  return p;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

std::span<const std::uint8_t> bytes_of(const std::vector<std::int64_t>& v) {
  return {reinterpret_cast<const std::uint8_t*>(v.data()), v.size() * sizeof(std::int64_t)};
}

std::vector<std::int64_t> integers(std::string_view bytes) {
  std::vector<std::int64_t> v(bytes.size() / sizeof(std::int64_t));
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(std::int64_t));
  return v;
}

// Whether the run's last stored front holds `p` exactly (cells and the values' bits).
bool repeats_last_front(sql::Database& db, std::int64_t controller_id, int run, const PackedMembers& p) {
  auto q = db.prepare("SELECT cells, objectives, descriptors FROM member_generations WHERE controller_id = ?1 AND "
                      "run = ?2 ORDER BY generation DESC LIMIT 1");
  q.bind(1, controller_id).bind(2, run);
  return q.step() && integers(q.bytes(0)) == p.cells && same_bits(q.doubles(1), p.objectives) &&
         same_bits(q.doubles(2), p.descriptors);
}

void insert_members(sql::Database& db, std::int64_t controller_id, std::int64_t run, std::int64_t generation,
                    const PackedMembers& p) {
  db.prepare("INSERT INTO member_generations(controller_id, run, generation, members, cells, objectives, descriptors) "
             "VALUES (?, ?, ?, ?, ?, ?, ?)")
      .bind(1, controller_id).bind(2, run).bind(3, generation).bind(4, static_cast<std::int64_t>(p.cells.size()))
      .bind_blob(5, bytes_of(p.cells)).bind_blob(6, std::span<const double>(p.objectives))
      .bind_blob(7, std::span<const double>(p.descriptors))
      .run();
  seal_row(db, "member_generations", db.last_insert_rowid());
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
  const PackedMembers p = pack(state.members);
  if (p.cells.empty()) return;   // an archive that changed nowhere
  if (layout.kind == evo::MemberKind::Front && repeats_last_front(db, controller_id, state.run, p)) return;
  insert_members(db, controller_id, state.run, generation, p);
}

std::optional<StoredMembers> load_members(sql::Database& db, std::int64_t controller_id, bool packed,
                                         std::string_view damaged) {
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
  if (!packed) {   // schemas 8 and 9: a row per member
    auto rows = db.prepare("SELECT run, generation, cell, objectives, descriptors FROM members WHERE controller_id = ? "
                           "ORDER BY run, generation, idx");
    rows.bind(1, controller_id);
    while (rows.step())
      s.rows.push_back({rows.integer(0), rows.integer(1), rows.int64(2), rows.doubles(3), rows.doubles(4)});
    return s;
  }
  auto rows = db.prepare("SELECT run, generation, members, cells, objectives, descriptors FROM member_generations "
                         "WHERE controller_id = ? ORDER BY run, generation");
  rows.bind(1, controller_id);
  while (rows.step()) {
    const auto n = static_cast<std::size_t>(rows.int64(2));
    const std::vector<std::int64_t> cells = integers(rows.bytes(3));
    const std::vector<double> objectives = rows.doubles(4);
    const std::vector<double> descriptors = rows.doubles(5);
    if (n == 0 || cells.size() != n || objectives.size() % n != 0 || descriptors.size() % n != 0)
      throw StoreError(fmt::format("{}: the members of run {}, generation {} do not fit their count", damaged,
                                   rows.integer(0) + 1, rows.integer(1)));
    const std::size_t k = objectives.size() / n, d = descriptors.size() / n;
    for (std::size_t i = 0; i < n; ++i)
      s.rows.push_back({rows.integer(0), rows.integer(1), cells[i],
                        {objectives.begin() + static_cast<std::ptrdiff_t>(i * k), objectives.begin() + static_cast<std::ptrdiff_t>((i + 1) * k)},
                        {descriptors.begin() + static_cast<std::ptrdiff_t>(i * d), descriptors.begin() + static_cast<std::ptrdiff_t>((i + 1) * d)}});
  }
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

void pack_member_rows(sql::Database& db) {
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;   // controller, run, generation
  std::map<Key, std::vector<evo::Member>> generations;
  {   // finished before the table is dropped
    auto q = db.prepare("SELECT controller_id, run, generation, cell, objectives, descriptors FROM members "
                        "ORDER BY controller_id, run, generation, idx");
    while (q.step()) {
      evo::Member m;
      m.cell = q.int64(3);
      m.objectives = q.doubles(4);
      m.descriptors = q.doubles(5);
      generations[{q.int64(0), q.int64(1), q.int64(2)}].push_back(std::move(m));
    }
  }
  db.exec(kMemberGenerations);
  for (const auto& [key, members] : generations)
    insert_members(db, std::get<0>(key), std::get<1>(key), std::get<2>(key), pack(members));
  db.exec("DROP TABLE members;");
}

}  // namespace esc::store
