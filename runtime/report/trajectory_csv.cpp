#include "runtime/report/trajectory_csv.hpp"

#include <fmt/format.h>

namespace esc::report {

std::string trajectory_csv_header(const IrColumns& ir, std::size_t ranges, std::size_t radars) {
  std::string h = "epoch,step,time_s,x_m,y_m,heading_rad,left_command,right_command,left_speed_mps,right_speed_mps";
  for (std::size_t i = 0; i < ir.count; ++i) h += fmt::format(",{}{}", ir.name, i);
  for (std::size_t i = 0; i < ir.count; ++i) h += fmt::format(",light{}", i);
  for (std::size_t i = 0; i < ranges; ++i) h += fmt::format(",range{}", i);
  for (std::size_t i = 0; i < radars; ++i) h += fmt::format(",radar{}", i);
  return h + ",energy,behavior,fitness,collided";
}

std::string trajectory_csv(std::span<const eval::TraceStep> steps, const std::vector<std::string>& choices,
                           double control_step_s, const IrColumns& ir) {
  const std::size_t ranges = steps.empty() ? 0 : steps.front().range_count;
  const std::size_t radars = steps.empty() ? 0 : steps.front().radar_count;
  std::string out = trajectory_csv_header(ir, ranges, radars) + "\n";
  for (const eval::TraceStep& t : steps) {
    const bool named = t.action >= 0 && static_cast<std::size_t>(t.action) < choices.size();
    out += fmt::format("{},{},{:.10g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", t.epoch + 1, t.step + 1,
                       (t.step + 1) * control_step_s, t.pose.x_m, t.pose.y_m, t.pose.heading_rad, t.left_command,
                       t.right_command, t.left_speed_mps, t.right_speed_mps);
    for (std::size_t i = 0; i < ir.count; ++i) out += fmt::format(",{:.17g}", t.ir[i]);
    for (std::size_t i = 0; i < ir.count; ++i) out += fmt::format(",{:.17g}", t.light[i]);
    for (std::size_t i = 0; i < ranges; ++i) out += fmt::format(",{:.17g}", t.range[i]);
    for (std::size_t i = 0; i < radars; ++i) out += fmt::format(",{:.17g}", t.radar[i]);
    out += fmt::format(",{:.17g},{},{:.17g},{}\n", t.energy, named ? choices[static_cast<std::size_t>(t.action)] : "",
                       t.fitness, t.collided ? 1 : 0);
  }
  return out;
}

}  // namespace esc::report
