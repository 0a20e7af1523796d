// Robots: `robot NAME [= BASE] { SETTING VALUE ... }` -> sim::RobotParams.
#include "compiler/lower_robot.hpp"

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/robot_settings.hpp"
#include "compiler/rule_messages.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::compiler {

bool RobotLowering::apply(LoweredRobot& robot, const std::vector<ast::Setting>& settings) {
  bool ok = true;
  std::map<std::string, const ast::Setting*> seen;
  for (const ast::Setting& s : settings) {
    if (s.key.text.empty()) {
      ok = false;
      continue;
    }
    const RobotSetting* info = find_robot_setting(s.key.text);
    if (info == nullptr) {
      suggest(sink_.error(s.key.where, fmt::format("unknown robot setting `{}`", s.key.text)), s.key.text,
              robot_setting_names(),
              {.otherwise = fmt::format("robot settings: {}", fmt::join(robot_setting_names(), ", "))});
      ok = false;
      continue;
    }
    if (auto [it, fresh] = seen.try_emplace(s.key.text, &s); !fresh) {
      sink_.error(s.key.where, fmt::format("`{}` is already set in this block", s.key.text))
          .notes.emplace_back(it->second->key.where, "first set here");
      ok = false;
      continue;
    }
    if (s.value.kind == ast::Value::Kind::Quantity && !s.value.q.finite) {   // reported by the parser
      ok = false;
      continue;
    }
    if (!apply_robot_value(*info, s.value, robot.params, sink_)) {
      ok = false;
      continue;
    }
    LoweredRobot::Written& w = robot.written[info->name] = {s.value.where, ++order_, {}};
    for (const ast::QuantityTuple& t : s.value.tuples) w.items.push_back(t.where);
  }
  return ok;
}

bool RobotLowering::check(const LoweredRobot& robot, const SourceRange& fallback) {
  const auto problems = sim::robot_problems(robot.params);
  for (const sim::Problem& p : problems) {
    const sim::RuleInfo& rule = p.info();
    const LoweredRobot::Written* last = nullptr;
    const auto consider = [&](std::string_view setting) {
      const auto it = robot.written.find(setting);
      if (it != robot.written.end() && (last == nullptr || it->second.order > last->order)) last = &it->second;
    };
    consider(rule.setting);
    for (std::string_view s : rule.also) consider(s);
    RuleMessage m = rule_message(p, RuleContext{nullptr, {}, &robot.params});
    SourceRange where = last != nullptr ? last->where : fallback;
    if (last != nullptr && p.index >= 0 && static_cast<std::size_t>(p.index) < last->items.size())
      where = last->items[static_cast<std::size_t>(p.index)];
    sink_.error(where, std::move(m.message)).help = std::move(m.help);
  }
  return problems.empty();
}

const std::optional<LoweredRobot>& RobotLowering::lower(const ast::RobotDecl& d) {
  if (auto it = robots_.find(&d); it != robots_.end()) return it->second;
  if (d.poisoned) return robots_[&d];
  if (in_progress_.count(&d) != 0) {
    sink_.error(d.name.where, fmt::format("robot `{}` is derived from itself", d.name.text));
    return robots_[&d];
  }
  in_progress_.insert(&d);
  std::optional<LoweredRobot> base = LoweredRobot{};
  if (d.base) {
    base.reset();
    if (const auto* b = names_.lookup<ast::RobotDecl>(*d.base)) base = lower(*b);
  }
  in_progress_.erase(&d);
  if (auto it = robots_.find(&d); it != robots_.end()) return it->second;   // set by a cycle report
  auto& slot = robots_[&d];
  if (!base) return slot;
  LoweredRobot r = std::move(*base);
  if (apply(r, d.settings) && check(r, d.name.where)) slot = std::move(r);
  return slot;
}

}  // namespace esc::compiler
