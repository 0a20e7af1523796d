#include "compiler/arena_settings.hpp"

#include <fmt/format.h>

#include "compiler/quantities.hpp"
#include "compiler/setting_keys.hpp"
#include "compiler/table_lookup.hpp"

namespace esc::compiler {

const std::vector<ArenaSetting>& arena_settings() {
  static const std::vector<ArenaSetting> table = {
      {"sweep_cell", &ast::ArenaDecl::sweep_cells, &sim::ArenaSpec::sweep_cell_m,
       "side of the area-sweeping grid's square cells (`new_cell`, `cells_visited`)"},
      {"reach_radius", &ast::ArenaDecl::reach_radii, &sim::ArenaSpec::reach_radius_m,
       "`reached(light)`: the robot's centre within this distance of the light"},
  };
  return table;
}

const ArenaSetting* find_arena_setting(std::string_view name) {
  return find_row(arena_settings(), &ArenaSetting::name, name);
}

std::vector<std::string> arena_setting_names() { return row_names(arena_settings(), &ArenaSetting::name); }

void resolve_arena_settings(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  const sim::ArenaSpec& a = spec.arena;
  r["arena"] = spec.arena_name;
  r["arena.size"] = fmt::format("{} m x {} m", number_text(a.width_m), number_text(a.height_m));
  r["arena.cylinders"] = std::to_string(a.cylinders.size());
  r["arena.blocks"] = std::to_string(a.boxes.size());
  r["arena.walls"] = std::to_string(a.walls.size());
  r["arena.goal"] =
      a.goal ? fmt::format("({} m, {} m)", number_text(a.goal->x), number_text(a.goal->y)) : std::string("none");
  r["arena.lights"] = std::to_string(a.lights.size());
  r["arena.zones"] = std::to_string(a.zones.size());
  for (const ArenaSetting& s : arena_settings())
    r[std::string(kArenaGroup).append(s.name)] = fmt::format("{} m", number_text(a.*s.value));
  if (a.fixed_start)
    r["arena.start"] = fmt::format("({} m, {} m) heading {} rad", number_text(a.fixed_start->x_m),
                                   number_text(a.fixed_start->y_m), number_text(a.fixed_start->heading_rad));
  else
    r["arena.start"] = "random";
}

}  // namespace esc::compiler
