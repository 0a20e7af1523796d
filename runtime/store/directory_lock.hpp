#pragma once
// An advisory lock on a run directory, held by every esc process that writes into it
// (flock(2) on the directory itself: no file is added). A second `esc run --out` that would
// reuse a directory holding nothing yet, or a second resume of a running directory, is
// refused while the first runs, instead of deleting or interleaving its files. The kernel
// drops the lock when the process ends, kill -9 included, so a killed run leaves none.
#include <filesystem>
#include <memory>

namespace esc::store {

class DirectoryLock {
 public:
  // The lock on `dir` (which must exist), shared within this process: acquiring a directory
  // this process already holds returns the same lock. Throws StoreError naming `dir` when
  // another process holds it. Where the file system cannot lock at all, runs unlocked.
  [[nodiscard]] static std::shared_ptr<const DirectoryLock> acquire(const std::filesystem::path& dir);

  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock();

 private:
  DirectoryLock(int fd, std::filesystem::path key) : fd_(fd), key_(std::move(key)) {}
  int fd_ = -1;                  // -1: the file system could not lock
  std::filesystem::path key_;    // the directory, canonical
};

}  // namespace esc::store
