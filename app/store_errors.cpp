#include "app/store_errors.hpp"

namespace esc::app {

bool no_room_left(const std::filesystem::path& dir) noexcept {
  constexpr std::uintmax_t kRoom = 1U << 20;
  std::error_code ec;
  std::filesystem::path at = std::filesystem::absolute(dir, ec);
  while (!at.empty() && !std::filesystem::exists(at, ec) && at != at.parent_path()) at = at.parent_path();
  const std::filesystem::space_info s = std::filesystem::space(at, ec);
  return !ec && s.available < kRoom;
}

}  // namespace esc::app
