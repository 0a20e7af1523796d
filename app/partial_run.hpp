#pragma once
// Where a dependency runs until it has finished: `ENTRY.partial-HOST-PID-TOKEN` beside its
// cache entry, renamed onto the entry when done. A lock file beside it
// (`ENTRY.partial-...lock`, flock) is held for as long as the owning process lives, so
// another process can tell a live run from one whose process was killed, whatever its PID
// namespace, and continue the latter instead of running it again.
#include <filesystem>
#include <functional>
#include <optional>

namespace esc::app {

class PartialRun {
 public:
  // A fresh name for cache entry `entry`, its lock held. Throws std::system_error when the
  // lock file cannot be made (the cache directory must exist).
  [[nodiscard]] static PartialRun create(const std::filesystem::path& entry);

  PartialRun(PartialRun&& other) noexcept;
  PartialRun& operator=(PartialRun&&) = delete;
  PartialRun(const PartialRun&) = delete;
  PartialRun& operator=(const PartialRun&) = delete;
  ~PartialRun();   // removes the lock file and releases it

  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }

 private:
  PartialRun(std::filesystem::path dir, int lock_fd) : dir_(std::move(dir)), lock_fd_(lock_fd) {}
  std::filesystem::path dir_;
  int lock_fd_ = -1;
};

// Held by the process that prepares an entry of a dependency cache: flock on the cache
// directory itself, so that processes sharing a cache run each entry once, the others
// waiting, then reusing it. No file is added to the cache (its entries are what users and
// tools list), at the price of one process preparing at a time. Released with the process,
// whatever ends it.
class CacheLock {
 public:
  // Blocks until the lock is held, calling `waiting` first when another process holds it.
  // Throws std::system_error when `cache` cannot be opened.
  [[nodiscard]] static CacheLock acquire(const std::filesystem::path& cache, const std::function<void()>& waiting);

  CacheLock(CacheLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  CacheLock& operator=(CacheLock&&) = delete;
  CacheLock(const CacheLock&) = delete;
  CacheLock& operator=(const CacheLock&) = delete;
  ~CacheLock();

 private:
  explicit CacheLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

// Looks at the runs of `entry` that processes of this machine started and left (their lock
// is free): removes those that hold no database yet, and moves the first that holds one
// onto `mine.dir()`, returning where it was. Runs of live processes and of other machines
// (a lock over a network filesystem proves little) are left alone.
std::optional<std::filesystem::path> take_over_abandoned(const std::filesystem::path& entry, const PartialRun& mine);

}  // namespace esc::app
