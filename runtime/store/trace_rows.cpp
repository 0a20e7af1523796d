#include "runtime/store/trace_rows.hpp"

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"

namespace esc::store {

namespace {

// A replay row: the kTraceColumns fixed columns, then the accumulator level, the position
// of each of the arena's zones in this epoch (x, y), the light sensors, and the rangefinders,
// goal radars, ground sensors and bumpers the robot declares. Traces stored before these
// columns existed have exactly kTraceColumns per row, or no light, range, radar, ground or
// bumper columns: the stored column names say which, so that a trace is read back as it was
// written.
// The numbered families after the lights, each named once: rangeK, radarK, ground_sensorK, bumperK.
constexpr std::string_view kRange = "range", kRadar = "radar", kGround = "ground_sensor", kBumper = "bumper";
// A group's replay ends each row with the robot (from 0) and its group observables, named as
// scripts name them.
constexpr std::string_view kRobot = "robot";
constexpr const auto& kGroupColumns = eval::kTracedGroupNames;

struct TraceLayout {
  bool extended = true;   // the accumulator and zones follow the fixed columns
  std::size_t zones = 0;
  bool lights = true;
  std::size_t ranges = 0;
  std::size_t radars = 0;
  std::size_t grounds = 0;
  std::size_t bumpers = 0;
  bool group = false;     // the robot and the group observables end the row

  [[nodiscard]] std::size_t width() const noexcept {
    if (!extended) return kTraceColumns;
    return kTraceColumns + 1 + 2 * zones + (lights ? static_cast<std::size_t>(sim::kLightSensors) : 0) + ranges +
           radars + grounds + bumpers + (group ? 1 + kGroupColumns.size() : 0);
  }

  // The column names of an extended layout with lights, in pack_trace's order.
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> c = {"epoch", "step", "x", "y", "heading"};
    for (int i = 0; i < sim::kIrSensors; ++i) c.push_back(fmt::format("ir{}", i));
    for (const char* n : {"left_command", "right_command", "left_speed", "right_speed", "action", kRunningFitness,
                          "collided"})
      c.emplace_back(n);
    c.emplace_back("energy");
    for (std::size_t z = 0; z < zones; ++z) {
      c.push_back(fmt::format("zone{}_x", z));
      c.push_back(fmt::format("zone{}_y", z));
    }
    for (int i = 0; i < sim::kLightSensors; ++i) c.push_back(fmt::format("light{}", i));
    for (const auto& [family, count] : {std::pair{kRange, ranges}, std::pair{kRadar, radars},
                                        std::pair{kGround, grounds}, std::pair{kBumper, bumpers}})
      for (std::size_t i = 0; i < count; ++i) c.push_back(fmt::format("{}{}", family, i));
    if (group) {
      c.emplace_back(kRobot);
      c.insert(c.end(), kGroupColumns.begin(), kGroupColumns.end());
    }
    return c;
  }
};

TraceLayout layout_of(std::span<const eval::TraceStep> trace) {
  if (trace.empty()) return {};
  const eval::TraceStep& t = trace.front();
  return {true, t.zone_count, true, t.range_count, t.radar_count, t.ground_count, t.bumper_count, t.grouped};
}

// Whether column `c` is `prefix` followed by a number: light3, range0.
bool numbered(std::string_view c, std::string_view prefix) {
  return c.size() > prefix.size() && c.starts_with(prefix) &&
         std::all_of(c.begin() + static_cast<std::ptrdiff_t>(prefix.size()), c.end(),
                     [](char ch) { return ch >= '0' && ch <= '9'; });
}

std::size_t count_prefixed(const std::vector<std::string>& columns, std::string_view prefix) {
  return static_cast<std::size_t>(
      std::count_if(columns.begin(), columns.end(), [&](const std::string& c) { return numbered(c, prefix); }));
}

// Whether this esc knows the stored column: a fixed one (the running fitness also under its
// first name, `fitness`), the accumulator, or one of a numbered family. A column it does not
// know was written by a newer esc.
bool known_column(const std::string& c) {
  static const std::vector<std::string> fixed = [] {
    std::vector<std::string> names = TraceLayout{.group = true}.names();
    names.emplace_back("fitness");
    return names;
  }();
  if (std::find(fixed.begin(), fixed.end(), c) != fixed.end()) return true;
  if (c.starts_with("zone") && (c.ends_with("_x") || c.ends_with("_y"))) return true;
  for (const std::string_view family : {kRange, kRadar, kGround, kBumper})
    if (numbered(c, family)) return true;
  return false;
}

TraceLayout layout_of(const std::vector<std::string>& columns) {
  for (const std::string& c : columns)
    if (!known_column(c))
      throw StoreError(fmt::format("the database was written by a newer esc: its replay traces have a column `{}` "
                                   "this esc does not know",
                                   c));
  TraceLayout l;
  l.extended = columns.size() > kTraceColumns;
  l.zones = static_cast<std::size_t>(std::count_if(columns.begin(), columns.end(), [](const std::string& c) {
    return c.starts_with("zone") && c.ends_with("_x");
  }));
  l.lights = count_prefixed(columns, "light") != 0;
  l.ranges = count_prefixed(columns, kRange);
  l.radars = count_prefixed(columns, kRadar);
  l.grounds = count_prefixed(columns, kGround);
  l.bumpers = count_prefixed(columns, kBumper);
  l.group = std::find(columns.begin(), columns.end(), kRobot) != columns.end();
  return l;
}

}  // namespace

std::vector<double> pack_trace(std::span<const eval::TraceStep> trace) {
  const TraceLayout layout = layout_of(trace);
  std::vector<double> v;
  v.reserve(trace.size() * layout.width());
  for (const auto& t : trace) {
    v.push_back(t.epoch);
    v.push_back(t.step);
    v.push_back(t.pose.x_m);
    v.push_back(t.pose.y_m);
    v.push_back(t.pose.heading_rad);
    v.insert(v.end(), t.ir.begin(), t.ir.end());
    v.push_back(t.left_command);
    v.push_back(t.right_command);
    v.push_back(t.left_speed_mps);
    v.push_back(t.right_speed_mps);
    v.push_back(t.action);
    v.push_back(t.fitness);
    v.push_back(t.collided ? 1.0 : 0.0);
    v.push_back(t.energy);
    for (std::size_t z = 0; z < layout.zones; ++z) {
      v.push_back(t.zones[z].x);
      v.push_back(t.zones[z].y);
    }
    v.insert(v.end(), t.light.begin(), t.light.end());
    v.insert(v.end(), t.range.begin(), t.range.begin() + static_cast<std::ptrdiff_t>(layout.ranges));
    v.insert(v.end(), t.radar.begin(), t.radar.begin() + static_cast<std::ptrdiff_t>(layout.radars));
    v.insert(v.end(), t.ground.begin(), t.ground.begin() + static_cast<std::ptrdiff_t>(layout.grounds));
    v.insert(v.end(), t.bumper.begin(), t.bumper.begin() + static_cast<std::ptrdiff_t>(layout.bumpers));
    if (layout.group) {
      v.push_back(t.robot);
      v.insert(v.end(), t.group.begin(), t.group.end());
    }
  }
  return v;
}

std::vector<eval::TraceStep> unpack_trace(const std::vector<double>& v, const std::vector<std::string>& columns) {
  const std::size_t width = columns.size();
  const TraceLayout layout = layout_of(columns);
  if (width < kTraceColumns || layout.width() != width || layout.zones > sim::kMaxZones ||
      layout.ranges > static_cast<std::size_t>(sim::kMaxRangefinders) ||
      layout.radars > static_cast<std::size_t>(sim::kMaxRadars) ||
      layout.grounds > static_cast<std::size_t>(sim::kMaxGroundSensors) ||
      layout.bumpers > static_cast<std::size_t>(sim::kMaxBumpers))
    throw StoreError(fmt::format("the database is damaged: a replay trace has {} columns", width));
  if (v.size() % width != 0) throw StoreError("the database is damaged: a replay trace has a partial row");
  std::vector<eval::TraceStep> out(v.size() / width);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double* r = &v[i * width];
    eval::TraceStep& t = out[i];
    t.epoch = static_cast<int>(r[0]);
    t.step = static_cast<int>(r[1]);
    t.pose = {r[2], r[3], r[4]};
    for (std::size_t k = 0; k < t.ir.size(); ++k) t.ir[k] = r[5 + k];
    t.left_command = r[13];
    t.right_command = r[14];
    t.left_speed_mps = r[15];
    t.right_speed_mps = r[16];
    t.action = static_cast<int>(r[17]);
    t.fitness = r[18];
    t.collided = r[19] != 0.0;
    if (!layout.extended) continue;
    const double* c = r + kTraceColumns;
    t.energy = *c++;
    t.zone_count = layout.zones;
    for (std::size_t z = 0; z < layout.zones; ++z, c += 2) t.zones[z] = {c[0], c[1]};
    if (layout.lights)
      for (double& l : t.light) l = *c++;
    t.range_count = layout.ranges;
    for (std::size_t k = 0; k < layout.ranges; ++k) t.range[k] = *c++;
    t.radar_count = layout.radars;
    for (std::size_t k = 0; k < layout.radars; ++k) t.radar[k] = *c++;
    t.ground_count = layout.grounds;
    for (std::size_t k = 0; k < layout.grounds; ++k) t.ground[k] = *c++;
    t.bumper_count = layout.bumpers;
    for (std::size_t k = 0; k < layout.bumpers; ++k) t.bumper[k] = *c++;
    if (!layout.group) continue;
    t.robot = static_cast<int>(*c++);
    t.grouped = true;
    for (double& g : t.group) g = *c++;
  }
  return out;
}

std::vector<std::string> trace_columns(std::span<const eval::TraceStep> trace) { return layout_of(trace).names(); }

}  // namespace esc::store
