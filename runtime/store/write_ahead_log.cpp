#include "runtime/store/write_ahead_log.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace {

constexpr std::size_t kHeaderBytes = 32;
constexpr std::size_t kFrameHeaderBytes = 24;
constexpr std::uint32_t kMagic = 0x377f0682;   // | 1: checksums over big-endian words
constexpr std::uint32_t kVersion = 3007000;

std::uint32_t big_endian(std::span<const std::uint8_t> at) {
  return std::uint32_t{at[0]} << 24 | std::uint32_t{at[1]} << 16 | std::uint32_t{at[2]} << 8 | std::uint32_t{at[3]};
}

std::uint32_t little_endian(std::span<const std::uint8_t> at) {
  return std::uint32_t{at[3]} << 24 | std::uint32_t{at[2]} << 16 | std::uint32_t{at[1]} << 8 | std::uint32_t{at[0]};
}

bool valid_page_size(std::uint32_t bytes) { return bytes >= 512 && bytes <= 65536 && (bytes & (bytes - 1)) == 0; }

// SQLite's cumulative log checksum (walChecksumBytes): over pairs of 32-bit words, in the
// byte order the header's magic names, continuing from `sum`.
using Checksum = std::array<std::uint32_t, 2>;
Checksum checksum(std::span<const std::uint8_t> bytes, bool big_endian_words, Checksum sum) {
  for (std::size_t i = 0; i + 8 <= bytes.size(); i += 8) {
    const auto word = [&](std::size_t at) {
      return big_endian_words ? big_endian(bytes.subspan(at, 4)) : little_endian(bytes.subspan(at, 4));
    };
    sum[0] += word(i) + sum[1];
    sum[1] += word(i + 4) + sum[0];
  }
  return sum;
}

Checksum stored_checksum(std::span<const std::uint8_t> at) { return {big_endian(at), big_endian(at.subspan(4))}; }

// The first `at_most` bytes of `file` (fewer where it is shorter).
std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file, std::uintmax_t at_most) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  std::ifstream in(file, std::ios::binary);
  if (ec || !in) throw StoreError(fmt::format("cannot read {}", file.string()));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(std::min(size, at_most)));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// The page size a database's header names (bytes 16-17, big-endian; 1 stands for 65536),
// or SQLite's default where it names none.
std::uint32_t database_page_size(const std::filesystem::path& database) {
  constexpr std::uint32_t kDefault = 4096;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(database, ec)) return kDefault;
  const std::vector<std::uint8_t> header = read_bytes(database, 18);
  if (header.size() < 18) return kDefault;
  const std::uint32_t size = std::uint32_t{header[16]} << 8 | header[17];
  if (size == 1) return 65536;
  return valid_page_size(size) ? size : kDefault;
}

}  // namespace

LogScan scan_log(std::span<const std::uint8_t> log, std::uint32_t database_page_size) {
  LogScan scan;
  if (log.size() < kHeaderBytes) return scan;   // no frame: nothing to lose
  const std::uint32_t magic = big_endian(log);
  const std::uint32_t header_page_size = big_endian(log.subspan(8));
  const bool big_endian_words = (magic & 1) != 0;
  const std::span<const std::uint8_t> salts = log.subspan(16, 8);
  // One salt as the header's: the log's current contents, a flipped bit in a salt included.
  const auto current = [&](std::span<const std::uint8_t> frame) {
    return std::equal(salts.begin(), salts.begin() + 4, frame.begin() + 8) ||
           std::equal(salts.begin() + 4, salts.end(), frame.begin() + 12);
  };
  Checksum sum = checksum(log.first(24), big_endian_words, {0, 0});
  // SQLite's recovery (walIndexRecover) reads no frame past a header that fails these.
  const bool header_valid = (magic & ~1U) == kMagic && valid_page_size(header_page_size) &&
                            sum == stored_checksum(log.subspan(24)) && big_endian(log.subspan(4)) == kVersion;
  const std::size_t page_bytes = valid_page_size(header_page_size) ? header_page_size : database_page_size;
  const std::size_t frame_bytes = kFrameHeaderBytes + page_bytes;
  scan.frames = static_cast<std::int64_t>((log.size() - kHeaderBytes) / frame_bytes);

  bool chained = header_valid;
  for (std::int64_t i = 0; i < scan.frames; ++i) {
    const std::span<const std::uint8_t> frame =
        log.subspan(kHeaderBytes + static_cast<std::size_t>(i) * frame_bytes, frame_bytes);
    const bool same_salts = std::equal(salts.begin(), salts.end(), frame.begin() + 8);
    if (chained) {
      sum = checksum(frame.subspan(kFrameHeaderBytes), big_endian_words, checksum(frame.first(8), big_endian_words, sum));
      chained = same_salts && big_endian(frame) != 0 && sum == stored_checksum(frame.subspan(16));
    }
    if (chained) {
      scan.valid = i + 1;
      if (big_endian(frame.subspan(4)) != 0) scan.committed = i + 1;   // the database's size after a commit
      continue;
    }
    scan.damaged = scan.damaged || current(frame);
  }
  // Lost: what the log holds past its last valid commit, whether the frames failed their
  // checks or belonged to a transaction that ended with one that did.
  for (std::int64_t i = scan.committed; i < scan.frames; ++i)
    if (current(log.subspan(kHeaderBytes + static_cast<std::size_t>(i) * frame_bytes, frame_bytes))) ++scan.lost;
  return scan;
}

std::optional<LogScan> log_damage(const std::filesystem::path& database) {
  const std::filesystem::path log = database.string() + "-wal";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(log, ec)) return std::nullopt;
  const std::vector<std::uint8_t> bytes = read_bytes(log, static_cast<std::uintmax_t>(-1));
  const LogScan scan = scan_log(bytes, database_page_size(database));
  if (!scan.damaged) return std::nullopt;
  return scan;
}

std::string log_damage_text(const std::filesystem::path& database, const LogScan& scan) {
  return fmt::format("{}-wal holds {} frame{} past its last valid commit (a damaged write-ahead log)",
                     database.string(), scan.lost, scan.lost == 1 ? "" : "s");
}

}  // namespace esc::store
