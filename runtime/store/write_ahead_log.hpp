#pragma once
// What SQLite will silently drop from a run's write-ahead log (esc.db-wal). SQLite reads the
// log's frames up to the last commit frame whose salts match the log's header and whose
// cumulative checksum holds, and ignores the rest without a word: one flipped bit in a
// killed run's log would show an earlier commit as if it were the last. The log is read here
// byte by byte (format: sqlite.org/fileformat2.html#walformat), before SQLite opens the
// database (opening may fold the log into it or reset it), to say what is lost.
//
// The rule. A frame carries the log's current contents when its salt-1 or its salt-2 equals
// the header's (a checkpoint restarts the log with salt-1 incremented and salt-2 random, so
// a stale frame from before a restart matches neither; a flipped bit changes only one of
// them). The log is damaged when, past the frames SQLite reads (its valid prefix), it holds a
// complete frame carrying its current contents. Stale frames past the prefix, a trailing
// partial frame (a write cut short by a kill) and frames of a transaction that never
// committed are not damage. A header that fails its own check (magic, version, page size,
// checksum) makes SQLite ignore the whole log: damage when a frame carries its salts.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace esc::store {

// What a log holds (frames counted from 1; 0: none).
struct LogScan {
  std::int64_t frames = 0;      // complete frames in the file
  std::int64_t valid = 0;       // frames SQLite accepts: salts and checksums chain from the header
  std::int64_t committed = 0;   // the last commit frame among them: what SQLite reads
  std::int64_t lost = 0;        // frames past `committed` carrying the log's current contents
  bool damaged = false;         // a frame past `valid` carries the log's current contents
};

// Scans the bytes of a log. `database_page_size`: the database's page size, used when the
// header's is damaged.
[[nodiscard]] LogScan scan_log(std::span<const std::uint8_t> log, std::uint32_t database_page_size);

// Reads `database`'s log (the file beside it named with "-wal" appended) without changing
// either: its scan when the log is damaged, nothing when it is not (or there is no log).
// Throws StoreError when the log exists but cannot be read.
[[nodiscard]] std::optional<LogScan> log_damage(const std::filesystem::path& database);

// "DATABASE-wal holds N frames past its last valid commit (a damaged write-ahead log)": what a
// damaged log lost, for the caller to say what follows from it.
[[nodiscard]] std::string log_damage_text(const std::filesystem::path& database, const LogScan& scan);

}  // namespace esc::store
