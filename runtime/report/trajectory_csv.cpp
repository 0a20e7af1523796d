#include "runtime/report/trajectory_csv.hpp"

#include <fmt/format.h>

namespace esc::report {

std::string trajectory_csv_header(const SensorColumns& sensors, std::size_t ranges, std::size_t radars,
                                  std::size_t grounds, std::size_t bumpers, bool group) {
  std::string h = group ? "epoch,step,robot" : "epoch,step";
  h += ",time_s,x_m,y_m,heading_rad,left_command,right_command,left_speed_mps,right_speed_mps";
  for (std::size_t i = 0; i < sensors.ir_count; ++i) h += fmt::format(",{}{}", sensors.ir, i);
  for (std::size_t i = 0; i < sensors.ir_count; ++i) h += fmt::format(",light{}", i);
  for (std::size_t i = 0; i < ranges; ++i) h += fmt::format(",range{}", i);
  for (std::size_t i = 0; i < radars; ++i) h += fmt::format(",radar{}", i);
  for (std::size_t i = 0; i < grounds; ++i) h += fmt::format(",{}{}", sensors.ground, i);
  for (std::size_t i = 0; i < bumpers; ++i) h += fmt::format(",bumper{}", i);
  h += ",energy,behavior,fitness,collided";
  if (group)
    for (const std::string_view name : eval::kTracedGroupNames) h += fmt::format(",{}_m", name);
  return h;
}

std::string trajectory_csv(std::span<const eval::TraceStep> steps, const std::vector<std::string>& choices,
                           double control_step_s, const SensorColumns& sensors) {
  const eval::TraceStep none;
  const eval::TraceStep& shape = steps.empty() ? none : steps.front();
  std::string out = trajectory_csv_header(sensors, shape.range_count, shape.radar_count, shape.ground_count,
                                          shape.bumper_count, shape.grouped) +
                    "\n";
  for (const eval::TraceStep& t : steps) {
    const bool named = t.action >= 0 && static_cast<std::size_t>(t.action) < choices.size();
    out += fmt::format("{},{}", t.epoch + 1, t.step + 1);
    if (shape.grouped) out += fmt::format(",{}", t.robot + 1);
    out += fmt::format(",{:.10g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", (t.step + 1) * control_step_s,
                       t.pose.x_m, t.pose.y_m, t.pose.heading_rad, t.left_command, t.right_command, t.left_speed_mps,
                       t.right_speed_mps);
    for (std::size_t i = 0; i < sensors.ir_count; ++i) out += fmt::format(",{:.17g}", t.ir[i]);
    for (std::size_t i = 0; i < sensors.ir_count; ++i) out += fmt::format(",{:.17g}", t.light[i]);
    for (std::size_t i = 0; i < shape.range_count; ++i) out += fmt::format(",{:.17g}", t.range[i]);
    for (std::size_t i = 0; i < shape.radar_count; ++i) out += fmt::format(",{:.17g}", t.radar[i]);
    for (std::size_t i = 0; i < shape.ground_count; ++i) out += fmt::format(",{:.17g}", t.ground[i]);
    for (std::size_t i = 0; i < shape.bumper_count; ++i) out += fmt::format(",{:.17g}", t.bumper[i]);
    out += fmt::format(",{:.17g},{},{:.17g},{}", t.energy, named ? choices[static_cast<std::size_t>(t.action)] : "",
                       t.fitness, t.collided ? 1 : 0);
    if (shape.grouped)
      for (const double g : t.group) out += fmt::format(",{:.17g}", g);
    out += '\n';
  }
  return out;
}

}  // namespace esc::report
