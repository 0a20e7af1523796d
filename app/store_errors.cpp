#include "app/store_errors.hpp"

#include <unistd.h>

namespace esc::app {

namespace {

std::filesystem::path nearest_existing(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::path at = std::filesystem::absolute(dir.empty() ? std::filesystem::path(".") : dir, ec);
  while (!at.empty() && !std::filesystem::exists(at, ec) && at != at.parent_path()) at = at.parent_path();
  return at;
}

}  // namespace

void require_writable(const std::filesystem::path& dir, const std::string& what, const std::string& help) {
  const std::filesystem::path at = nearest_existing(dir);
  // access() answers for this process: its user, and a read-only mount (EROFS).
  if (!at.empty() && ::access(at.c_str(), W_OK) != 0)
    throw Error(ErrorKind::Results, fmt::format("{} is read-only: {}", at.string(), what), help);
}

bool no_room_left(const std::filesystem::path& dir) noexcept {
  constexpr std::uintmax_t kRoom = 1U << 20;
  std::error_code ec;
  const std::filesystem::space_info s = std::filesystem::space(nearest_existing(dir), ec);
  return !ec && s.available < kRoom;
}

}  // namespace esc::app
