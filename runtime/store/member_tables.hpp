#pragma once
// What the results database keeps of the members an optimizer holds beside a run's best
// (schema 8; evo::Optimizer::members): NSGA-II's first front, MAP-Elites' archive, novelty
// search's archive of behaviors. Per controller its layout (table member_layouts: the
// values' names, an archive's cells), and per generation of each run its members (table
// member_generations, one row holding them all since schema 10): an archive's changed cells
// every generation, so that the archive of any
// generation is the last row of each cell up to it; a front whole at the generations that
// are multiples of the experiment's members_every and at the run's last, except where it
// equals the run's last stored front (bit for bit): there it is unchanged, and the front of
// such a generation is the last stored up to it. Genomes are not stored per generation:
// the final front or archive is in the run's optimizer state (what `esc replay` reads).
// Written in the generation's transaction, so a resumed run stores exactly what the
// uninterrupted one would.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

inline constexpr int kMemberSchemaVersion = 8;
inline constexpr int kPackedMemberSchemaVersion = 10;

// "front" or "archive", as the store and exports name a kind.
[[nodiscard]] const char* member_kind_name(evo::MemberKind kind);

// The tables, for a new database and for the upgrade to schema 8.
[[nodiscard]] std::string member_schema();
// Upgrading a schema-8 or 9 database to 10: its table members, a row per member, becomes
// member_generations, a row per generation (the same values, bit for bit).
void pack_member_rows(sql::Database& db);

// One stored member: of run `run` (from 0) at generation `generation`.
struct StoredMember {
  int run = 0;
  int generation = 0;
  std::int64_t cell = 0;
  std::vector<double> objectives;    // as measured (a minimised objective not negated)
  std::vector<double> descriptors;
};

struct StoredMembers {
  eval::MemberLayout layout;
  std::vector<StoredMember> rows;    // by run, generation, then as the optimizer listed them
};

// Generation `generation`'s members of a run (state.member_layout set) where it stores them
// (state.members_due) and a front has changed, the controller's layout with the first.
void save_members(sql::Database& db, std::int64_t controller_id, const eval::RunState& state, int generation);
// What a controller's runs stored, or nullopt when its optimizer keeps no members; `packed`:
// the database has schema 10's member_generations (else 8's or 9's members). Throws
// StoreError, its message starting with `damaged`, for a row whose values do not fit its count.
[[nodiscard]] std::optional<StoredMembers> load_members(sql::Database& db, std::int64_t controller_id, bool packed,
                                                        std::string_view damaged);

// The archive of `run` after generation `generation`: each cell's last row up to it, in
// cell order (for a front: the rows of the last generation up to it that stored one, which is
// generation `generation`'s front where that generation is one that stores it).
[[nodiscard]] std::vector<StoredMember> members_at(const StoredMembers& members, int run, int generation);

}  // namespace esc::store
