#include "runtime/eval/settings_history.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>

namespace esc::eval {

namespace {

// (key, value as resolved_settings writes it), in the order they were added.
constexpr std::array<std::pair<std::string_view, std::string_view>, 6> kAdded{{
    {"robot.motor_noise", "0"},   // 2026-12-02
    // The maze navigator's walls, goal and sensors: none, and the rangefinders' default range.
    {"arena.walls", "0"},
    {"arena.goal", "none"},
    {"robot.rangefinders", "[]"},
    {"robot.rangefinder_range", "0.34375 m"},
    {"robot.radars", "0"},
}};

}  // namespace

bool as_before_it_existed(const std::string& key, const std::string& value) {
  return std::any_of(kAdded.begin(), kAdded.end(), [&](const auto& a) { return a.first == key && a.second == value; });
}

bool same_settings(const std::map<std::string, std::string>& now, const std::map<std::string, std::string>& stored) {
  for (const auto& [key, value] : now) {
    const auto it = stored.find(key);
    if (it == stored.end() ? !as_before_it_existed(key, value) : it->second != value) return false;
  }
  return std::all_of(stored.begin(), stored.end(), [&](const auto& kv) { return now.count(kv.first) != 0; });
}

}  // namespace esc::eval
