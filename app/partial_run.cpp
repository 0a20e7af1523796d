#include "app/partial_run.hpp"

#include <array>
#include <cctype>
#include <cerrno>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/format.h>

namespace esc::app {

namespace fs = std::filesystem;

namespace {

// This machine's name as it appears in `.partial-HOST-...` directories.
std::string host_name() {
  std::array<char, 256> buffer{};
  if (::gethostname(buffer.data(), buffer.size() - 1) != 0) return "localhost";
  std::string host(buffer.data());
  for (char& c : host)
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '-' && c != '.') c = '_';
  return host;
}

std::string prefix_of(const fs::path& entry) { return entry.filename().string() + ".partial-" + host_name() + "-"; }

fs::path lock_of(const fs::path& dir) { return dir.string() + ".lock"; }

int open_lock(const fs::path& lock) { return ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644); }

bool lock(int fd, bool wait) {
  int r = 0;
  while ((r = ::flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB))) != 0 && errno == EINTR) {}
  return r == 0;
}

}  // namespace

CacheLock CacheLock::acquire(const fs::path& cache, const std::function<void()>& waiting) {
  const int fd = ::open(cache.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), cache.string());
  if (!lock(fd, false)) {
    waiting();
    if (!lock(fd, true)) {
      const int error = errno;
      ::close(fd);
      throw std::system_error(error, std::generic_category(), cache.string());
    }
  }
  return CacheLock(fd);
}

CacheLock::~CacheLock() {
  if (fd_ >= 0) ::close(fd_);   // closing the descriptor releases the lock
}

PartialRun PartialRun::create(const fs::path& entry) {
  // Host and PID say who made it; the token keeps names apart when neither does (two
  // containers with one host name, both PID 1).
  const auto token = std::random_device{}();
  fs::path dir = entry.parent_path() / fmt::format("{}{}-{:08x}", prefix_of(entry), ::getpid(), token);
  const int fd = open_lock(lock_of(dir));
  if (fd < 0) throw std::system_error(errno, std::generic_category(), lock_of(dir).string());
  if (!lock(fd, true)) {
    const int error = errno;
    ::close(fd);
    throw std::system_error(error, std::generic_category(), lock_of(dir).string());
  }
  return {std::move(dir), fd};
}

PartialRun::PartialRun(PartialRun&& other) noexcept : dir_(std::move(other.dir_)), lock_fd_(other.lock_fd_) {
  other.lock_fd_ = -1;
}

PartialRun::~PartialRun() {
  if (lock_fd_ < 0) return;
  ::unlink(lock_of(dir_).c_str());
  ::close(lock_fd_);
}

std::optional<fs::path> take_over_abandoned(const fs::path& entry, const PartialRun& mine) {
  const std::string prefix = prefix_of(entry);
  std::vector<fs::path> candidates;
  std::error_code ec;
  for (auto it = fs::directory_iterator(entry.parent_path(), ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) == 0 && it->is_directory(ec) && it->path() != mine.dir()) candidates.push_back(it->path());
  }
  std::optional<fs::path> taken;
  for (const fs::path& dir : candidates) {
    const int fd = open_lock(lock_of(dir));
    if (fd < 0) continue;
    if (!lock(fd, false)) {   // its process is alive
      ::close(fd);
      continue;
    }
    // Ours now: no other process can take or remove it while the lock is held.
    bool gone = false;
    if (!fs::exists(dir / "esc.db", ec)) {
      fs::remove_all(dir, ec);
      gone = true;
    } else if (!taken) {
      fs::rename(dir, mine.dir(), ec);
      if (!ec) taken = dir;
      gone = !ec;
    }
    if (gone || !fs::exists(dir, ec)) ::unlink(lock_of(dir).c_str());
    ::close(fd);
  }
  return taken;
}

}  // namespace esc::app
