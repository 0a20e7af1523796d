#include "runtime/store/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <map>
#include <mutex>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace fs = std::filesystem;

namespace {

// The locks this process holds, by canonical directory: flock(2) locks of two descriptors
// of one directory conflict even within one process, so a second acquire must share.
std::mutex& held_mutex() {
  static std::mutex m;
  return m;
}

std::map<fs::path, std::weak_ptr<const DirectoryLock>>& held() {
  static std::map<fs::path, std::weak_ptr<const DirectoryLock>> locks;
  return locks;
}

}  // namespace

std::shared_ptr<const DirectoryLock> DirectoryLock::acquire(const fs::path& dir) {
  std::error_code ec;
  fs::path key = fs::canonical(dir, ec);
  if (ec) key = fs::absolute(dir, ec).lexically_normal();
  const std::lock_guard guard(held_mutex());
  if (auto it = held().find(key); it != held().end())
    if (auto lock = it->second.lock()) return lock;
  int fd = ::open(key.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK)
      throw StoreError(fmt::format("`{}` is in use by another esc process writing into it; wait for it to end",
                                   dir.string()));
    fd = -1;   // a file system without flock: unlocked, as before locks existed
  }
  std::shared_ptr<const DirectoryLock> lock(new DirectoryLock(fd, key));
  held()[key] = lock;
  return lock;
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);   // closing the descriptor releases the flock
  const std::lock_guard guard(held_mutex());
  if (auto it = held().find(key_); it != held().end() && it->second.expired()) held().erase(it);
}

}  // namespace esc::store
