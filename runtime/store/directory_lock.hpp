#pragma once
// An advisory lock on a run directory, held by every esc process that writes into it
// (flock(2) on the directory itself: no file is added). A second `esc run --out` that would
// reuse a directory holding nothing yet, or a second resume of a running directory, is
// refused while the first runs, instead of deleting or interleaving its files. The kernel
// drops the lock when the process ends, kill -9 included, so a killed run leaves none.
#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <utility>

namespace esc::store {

class DirectoryLock {
 public:
  // The lock on `dir`, shared within this process: acquiring a directory this process
  // already holds (by any path) returns the same lock. Throws StoreError naming `dir` when
  // another process holds it. A directory that does not exist, or a file system that cannot
  // lock, gives a lock that holds nothing.
  [[nodiscard]] static std::shared_ptr<const DirectoryLock> acquire(const std::filesystem::path& dir);

  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock();

 private:
  DirectoryLock(int fd, std::pair<dev_t, ino_t> key) : fd_(fd), key_(key) {}
  int fd_ = -1;                       // -1: nothing locked
  std::pair<dev_t, ino_t> key_{};     // the directory's device and inode
};

}  // namespace esc::store
