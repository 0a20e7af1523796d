#include "runtime/store/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <map>
#include <mutex>
#include <utility>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

// The locks this process holds, by directory (device and inode: whatever path reached it,
// and across a rename): flock(2) locks of two descriptors of one directory conflict even
// within one process, so a second acquire must share the first.
using Key = std::pair<dev_t, ino_t>;

std::mutex& held_mutex() {
  static std::mutex m;
  return m;
}

std::map<Key, std::weak_ptr<const DirectoryLock>>& held() {
  static std::map<Key, std::weak_ptr<const DirectoryLock>> locks;
  return locks;
}

}  // namespace

std::shared_ptr<const DirectoryLock> DirectoryLock::acquire(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  struct stat st {};
  if (fd < 0 || ::fstat(fd, &st) != 0) {   // not there: nothing to lock, nothing written yet
    if (fd >= 0) ::close(fd);
    return std::shared_ptr<const DirectoryLock>(new DirectoryLock(-1, {}));
  }
  const Key key{st.st_dev, st.st_ino};
  const std::lock_guard guard(held_mutex());
  if (auto it = held().find(key); it != held().end())
    if (auto lock = it->second.lock()) {
      ::close(fd);
      return lock;
    }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK)
      throw StoreError(fmt::format("`{}` is in use by another esc process writing into it; wait for it to end",
                                   dir.string()));
    // A file system without flock: unlocked, as before locks existed.
    return std::shared_ptr<const DirectoryLock>(new DirectoryLock(-1, {}));
  }
  std::shared_ptr<const DirectoryLock> lock(new DirectoryLock(fd, key));
  held()[key] = lock;
  return lock;
}

DirectoryLock::~DirectoryLock() {
  if (fd_ < 0) return;
  const std::lock_guard guard(held_mutex());
  ::close(fd_);   // releases the flock, under the registry's mutex: no acquire sees it half-gone
  if (auto it = held().find(key_); it != held().end() && it->second.expired()) held().erase(it);
}

}  // namespace esc::store
