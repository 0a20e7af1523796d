#include "runtime/eval/settings_history.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>

namespace esc::eval {

namespace {

// (key, value as resolved_settings writes it), in the order they were added.
constexpr std::array<std::pair<std::string_view, std::string_view>, 20> kAdded{{
    {"robot.motor_noise", "0"},   // 2026-12-02
    // The maze navigator's walls, goal and sensors: none, and the rangefinders' default range.
    {"arena.walls", "0"},
    {"arena.goal", "none"},
    {"robot.rangefinders", "[]"},
    {"robot.rangefinder_range", "0.34375 m"},
    {"robot.radars", "0"},
    // IR sensors as data (2026-12-05): the Khepera's mounts and Enki's curve for it.
    {"robot.ir_sensors",
     "[(1.1868238913561442 rad, 1.5707963267948966 rad), (0.7504915783575618 rad, 0.7853981633974483 rad), "
     "(0.22689280275926285 rad, 0.17453292519943295 rad), (-0.22689280275926285 rad, -0.17453292519943295 rad), "
     "(-0.7504915783575618 rad, -0.7853981633974483 rad), (-1.1868238913561442 rad, -1.5707963267948966 rad), "
     "(2.7576202181510405 rad, 3.141592653589793 rad), (-2.7576202181510405 rad, 3.141592653589793 rad)]"},
    {"robot.ir_curve_x0", "-0.009000000000000001 m"},
    {"robot.ir_curve_c", "0.0007 m2"},
    {"robot.ir_response", "[]"},
    {"robot.ir_name", "ir"},
    // The acceleration drive (2026-12-05): the differential drive, and the navigator's turning.
    {"robot.drive", "differential"},
    {"robot.max_turn_rate", "0.5235987755982988 rad/s"},
    {"robot.max_turn_accel", "0.8726646259971648 rad/s^2"},
    // Bodies of any convex outline (2026-12-05): the disc.
    {"robot.body_outline", "[]"},
    // Ground sensors at points under the body (2026-12-05): none.
    {"robot.ground_sensors", "[]"},
    {"robot.ground_name", "ground_sensor"},
    // Bumpers (2026-12-05): none.
    {"robot.bumpers", "[]"},
    // Light given off by a robot, for the others' light sensors (2026-12-06): none.
    {"robot.emission", "0"},
    {"robot.emission_height", "0 m"},
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
