#include "compiler/rule_messages.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace esc::compiler {

namespace {

using sim::Dimension;
using sim::Rule;

std::string number(double v) {
  if (v == 0.0) return "0";
  return fmt::format("{:.6g}", v);
}

std::string arena_text(const RuleContext& c) {
  if (c.arena == nullptr) return "";
  return fmt::format(" ({} x {})", shown(c.arena->width_m, Dimension::Length),
                     shown(c.arena->height_m, Dimension::Length));
}

std::string at_point(const sim::Vec2& p) {
  return fmt::format("({}, {})", shown(p.x, Dimension::Length), shown(p.y, Dimension::Length));
}

// "it reaches 1.5cm beyond a wall".
std::string beyond(const sim::Problem& p) {
  if (!std::isfinite(p.found)) return "";
  return fmt::format(": it reaches {} beyond a wall", shown(p.found, Dimension::Length));
}

// The smallest sweep cell (to the centimetre's hundredth) whose grid fits. The cell count
// falls as the cell grows, so bisection between a cell below the area's bound (too small)
// and one as large as the arena (one cell) finds it in bounded steps, however long and thin
// the arena: stepping up from the bound would take longer than any run for one such arena.
// Each step halves the gap or meets the spacing of large doubles, so it ends within about
// as many steps as a double has exponents.
std::string smallest_sweep_cell(const sim::ArenaSpec& a) {
  constexpr double kHundredthsPerMetre = 1e4;
  const auto fits = [&](double hundredths) {
    const double cell_m = hundredths / kHundredthsPerMetre;
    return std::ceil(a.width_m / cell_m) * std::ceil(a.height_m / cell_m) <= sim::kMaxSweepCells;
  };
  double too_small =
      std::max(0.0, std::floor(std::sqrt(a.width_m * a.height_m / sim::kMaxSweepCells) * kHundredthsPerMetre) - 1);
  double fitting = std::ceil(std::max(a.width_m, a.height_m) * kHundredthsPerMetre);
  while (fitting - too_small > 1) {
    const double middle = std::floor((too_small + fitting) / 2);
    if (middle <= too_small || middle >= fitting) break;   // beyond a double's integers
    (fits(middle) ? fitting : too_small) = middle;
  }
  return fmt::format("{}cm", number(fitting / 100));
}

// Generic: "`ir_aperture` must be below 180deg, found 200deg", with the reason for an upper limit.
RuleMessage bound(const sim::Problem& p, std::string_view subject) {
  const sim::RuleInfo& r = p.info();
  const std::string_view rel = r.relation == sim::Relation::Above ? "greater than" : sim::relation_words(r.relation);
  RuleMessage m{fmt::format("{} must be {} {}, found {}", subject, rel, shown(p.limit, r.dimension),
                            shown(p.found, r.dimension)),
                {}};
  if (r.relation == sim::Relation::AtMost || r.relation == sim::Relation::Below) m.help.emplace_back(r.why);
  return m;
}

RuleMessage arena_message(const sim::Problem& p, const RuleContext& c) {
  constexpr std::string_view kPositions = "positions are measured from the arena's lower-left inner corner";
  switch (p.rule) {
    case Rule::ArenaWidth: return bound(p, "the arena's width");
    case Rule::ArenaHeight: return bound(p, "the arena's height");
    case Rule::ObstacleCount:
      return {fmt::format("an arena holds at most {} blocks, cylinders and walls together", sim::kMaxObstacles),
              {std::string(p.info().why)}};
    case Rule::BlockSize: return {"a block's width and height must be greater than 0", {}};
    case Rule::BlockInside:
      return {fmt::format("this block is not inside the arena{}{}", arena_text(c), beyond(p)),
              {std::string(kPositions) + " to the block's centre"}};
    case Rule::CylinderRadius: return {"a cylinder's radius must be greater than 0", {}};
    case Rule::CylinderInside:
      return {fmt::format("this cylinder is not inside the arena{}{}", arena_text(c), beyond(p)),
              {std::string(kPositions)}};
    case Rule::WallLength: return {"a wall has a length: its two ends must not be the same point", {}};
    case Rule::WallThickness: return bound(p, "a wall's thickness");
    case Rule::WallInside:
      return {fmt::format("this wall is not inside the arena{}{}", arena_text(c), beyond(p)),
              {std::string(kPositions) + " to the wall's ends; a wall reaches half its thickness to either side"}};
    case Rule::GoalInside:
      return {fmt::format("the goal is outside the arena{}{}", arena_text(c), beyond(p)), {std::string(kPositions)}};
    case Rule::StartInside:
      return {fmt::format("the start position is outside the arena{}{}", arena_text(c), beyond(p)),
              {std::string(kPositions)}};
    case Rule::ZoneCount:
      return {fmt::format("an arena holds at most {} zones", sim::kMaxZones), {std::string(p.info().why)}};
    case Rule::ZoneRadius: return {"a zone's radius must be greater than 0", {}};
    case Rule::ZoneSize: return {"a zone's width and height must be greater than 0", {}};
    case Rule::ZoneInside:
      return {fmt::format("this zone is not inside the arena{}{}", arena_text(c), beyond(p)),
              {std::string(kPositions) + " to the zone's centre"}};
    case Rule::ZoneFits: return {fmt::format("this zone is larger than the arena{}", arena_text(c)), {}};
    case Rule::LightCount:
      return {fmt::format("an arena holds at most {} lights", sim::kMaxLights), {std::string(p.info().why)}};
    case Rule::LightHeight:
      return {fmt::format("a light's height must not be negative, found {}", shown(p.found, Dimension::Length)), {}};
    case Rule::LightIntensity:
      return {fmt::format("a light's intensity must not be negative, found {}", number(p.found)), {}};
    case Rule::LightZone: return {"this light stands above a zone its arena does not have", {}};
    case Rule::LightInside:
      return {fmt::format("this light is not inside the arena{}{}", arena_text(c), beyond(p)), {}};
    case Rule::SweepCell: return bound(p, "`sweep_cell`");
    case Rule::SweepGrid: {
      RuleMessage m{fmt::format("the area-sweeping grid of this arena{} would have {} cells, more than the {} the "
                                "simulator holds",
                                arena_text(c), shown(p.found, Dimension::Count), shown(p.limit, Dimension::Count)),
                    {}};
      if (c.arena != nullptr)
        m.help.push_back(fmt::format("write `sweep_cell {}` or larger in the arena, or make it smaller",
                                     smallest_sweep_cell(*c.arena)));
      return m;
    }
    case Rule::ReachRadius: return bound(p, "`reach_radius`");
    default: return bound(p, fmt::format("`{}`", p.info().setting));
  }
}

RuleMessage placement_message(const sim::Problem& p, const RuleContext& c) {
  const double r = c.robot != nullptr ? c.robot->body_radius_m : p.limit;
  switch (p.rule) {
    case Rule::RobotFits:
      return {fmt::format("the robot ({} across) does not fit in arena `{}`{}", shown(2 * r, Dimension::Length),
                          c.arena_name, arena_text(c)),
              {}};
    case Rule::StartClearOfWalls:
      return {fmt::format("the robot starting here would overlap a wall: its body radius is {}",
                          shown(r, Dimension::Length)),
              {}};
    case Rule::StartClearOfCylinder:
      return {
          fmt::format("the robot starting here would overlap the cylinder at {}",
                      c.arena != nullptr ? at_point(c.arena->cylinders.at(static_cast<std::size_t>(p.index)).center_m)
                                         : std::string("?")),
          {}};
    case Rule::StartClearOfBlock:
      return {fmt::format("the robot starting here would overlap the block at {}",
                          c.arena != nullptr ? at_point(c.arena->boxes.at(static_cast<std::size_t>(p.index)).center_m)
                                             : std::string("?")),
              {}};
    case Rule::StartClearOfWall: {
      if (c.arena == nullptr) return {"the robot starting here would overlap a wall", {}};
      const sim::WallSegment& w = c.arena->walls.at(static_cast<std::size_t>(p.index));
      return {fmt::format("the robot starting here would overlap the wall from {} to {}", at_point(w.from_m),
                          at_point(w.to_m)),
              {}};
    }
    default: return bound(p, fmt::format("`{}`", p.info().setting));
  }
}

// "a robot has at most 8 IR sensors, found 9", with the rule's reason.
RuleMessage too_many(const sim::Problem& p, std::string_view what) {
  return {fmt::format("a robot has at most {} {}, found {}", shown(p.limit, Dimension::Count), what,
                      shown(p.found, Dimension::Count)),
          {std::string(p.info().why)}};
}

// A sensor's mount point off the body: nearer than 0 (limit 0) or beyond the body's radius.
RuleMessage sits(const sim::Problem& p, std::string_view sensor, std::string_view help) {
  const std::string where = fmt::format("{} {} sits {} from the body's centre", sensor, p.index,
                                        shown(p.found, Dimension::Length));
  if (p.info().relation == sim::Relation::AtLeast) return {where + ": a distance is never negative", {}};
  RuleMessage m{fmt::format("{}, outside the body (radius {})", where, shown(p.limit, Dimension::Length)), {}};
  if (!help.empty()) m.help.emplace_back(help);
  return m;
}

RuleMessage robot_message(const sim::Problem& p, const RuleContext& c) {
  switch (p.rule) {
    case Rule::RangefinderCount: return too_many(p, "rangefinders");
    case Rule::IrCount: return too_many(p, "IR sensors");
    case Rule::IrMountRadiusMin: return sits(p, "IR sensor", {});
    case Rule::IrMountRadiusMax: return sits(p, "IR sensor", "leave the distance out for a sensor on the rim");
    case Rule::IrCurve:
      return {fmt::format("Enki's IR curve needs `ir_curve_c` above `ir_curve_x0` squared; c - x0^2 is {}cm2",
                          number(p.found)),
              {"the curve m (c - x0^2) / (x^2 - 2 x0 x + c) has a pole otherwise"}};
    case Rule::IrResponseCount:
      return {fmt::format("a measured IR response holds at most {} points, found {}", shown(p.limit, Dimension::Count),
                          shown(p.found, Dimension::Count)),
              {}};
    case Rule::IrResponseStart:
      return {fmt::format("the response's first distance is {}: a distance is never negative",
                          shown(p.found, Dimension::Length)),
              {}};
    case Rule::IrResponseDistance:
      return {fmt::format("the response's distances must increase: point {} is at {}, the point before at {}", p.index,
                          shown(p.found, Dimension::Length), shown(p.limit, Dimension::Length)),
              {}};
    case Rule::IrResponseReadingMin:
    case Rule::IrResponseReadingMax:
      return {fmt::format("point {} of the response reads {}: readings are normalised, 0 .. 1", p.index,
                          number(p.found)),
              {}};
    case Rule::NoiseWithoutWheels:
      return {fmt::format("`motor_noise` is an error of each wheel's speed, but this robot has the acceleration drive "
                          "(no wheels); found {}",
                          number(p.found)),
              {"leave `motor_noise` at 0, or use `drive differential`"}};
    case Rule::GroundCount: return too_many(p, "ground sensors");
    case Rule::BumperCount: return too_many(p, "bumpers");
    case Rule::BumperSectorMin:
    case Rule::BumperSectorMax:
      return {fmt::format("bumper {} spans {} from its first angle to its second, counter-clockwise", p.index,
                          shown(p.found, Dimension::Angle)),
              {"write a bumper as (from, to) with to above from by at most 360deg: (-45deg, 45deg) is the front "
               "quarter, (135deg, 225deg) the back one"}};
    case Rule::OutlineCorner:
      return {fmt::format("the outline's corner at vertex {} is {}, sharper than {}", p.index,
                          shown(p.found, Dimension::Angle), shown(p.limit, Dimension::Angle)),
              {std::string(p.info().why)}};
    case Rule::OutlineThin:
      return {"the outline is thinner than 2mm somewhere: moved in by 1mm, it turns inside out",
              {std::string(p.info().why)}};
    case Rule::GroundUnderOutline:
      return {fmt::format("ground sensor {} lies {} outside the body's outline", p.index,
                          shown(-p.found, Dimension::Length)),
              {"a ground sensor sits under the body"}};
    case Rule::GroundMountRadiusMin:
    case Rule::GroundMountRadiusMax: return sits(p, "ground sensor", {});
    case Rule::OutlineCountMin:
      return {fmt::format("an outline needs at least 3 vertices, found {}", shown(p.found, Dimension::Count)), {}};
    case Rule::OutlineCountMax:
      return {fmt::format("an outline holds at most {} vertices, found {}", shown(p.limit, Dimension::Count),
                          shown(p.found, Dimension::Count)),
              {}};
    case Rule::OutlineConvex:
      return {fmt::format("the outline is not convex at vertex {}: it turns the other way there, or not at all",
                          p.index),
              {"list a convex outline's vertices in order round the body, either way round"}};
    case Rule::OutlineAroundCentre:
      return {fmt::format("the outline does not hold the point the wheels turn about: that point lies {} outside an "
                          "edge",
                          shown(-p.found, Dimension::Length)),
              {"vertices are measured from the point the wheels turn about, x ahead and y to the left"}};
    case Rule::OutlineWithinRadius:
      return {fmt::format("outline vertex {} lies {} from the centre, beyond `body_radius` ({})", p.index,
                          shown(p.found, Dimension::Length), shown(p.limit, Dimension::Length)),
              {"`body_radius` is the circle around the outline: at least its farthest vertex"}};
    case Rule::OutlineWithoutWheels:
      return {"an outline needs the differential drive: the acceleration drive moves a disc",
              {"leave `body_outline` out, or use `drive differential`"}};
    case Rule::WheelBaseWithinBody:
      return {fmt::format("the wheel base ({}) is wider than the body ({} across)", shown(p.found, Dimension::Length),
                          shown(p.limit, Dimension::Length)),
              {std::string(p.info().why)}};
    case Rule::ContactLookAhead: {
      // In millimetres, the scale of a substep's travel.
      RuleMessage m{fmt::format("at full speed the rim of the robot moves {}mm per physics substep, more than the "
                                "{}mm the contact solver looks ahead",
                                number(p.found * 1000), number(p.limit * 1000)),
                    {}};
      if (c.robot != nullptr) {
        // In double: at an absurd speed the count overflows any integer.
        const double needed = std::ceil(p.found * c.robot->physics_substeps / p.limit);
        if (needed <= sim::kMaxPhysicsSubsteps)
          m.help.push_back(fmt::format("use `substeps {}` or more, or a lower `max_speed`", needed));
        else
          m.help.push_back(fmt::format("no `substeps` up to {} is enough: lower `max_speed` or `control_step`",
                                       sim::kMaxPhysicsSubsteps));
      }
      return m;
    }
    default: return bound(p, fmt::format("`{}`", p.info().setting));
  }
}

}  // namespace

std::string shown(double si, Dimension d) {
  if (si == 0.0) return "0";
  const double a = std::abs(si);
  switch (d) {
    case Dimension::Count:
      if (std::floor(si) == si && a < 1e15) return fmt::format("{}", static_cast<long long>(si));
      return number(si);
    case Dimension::Number: return number(si);
    case Dimension::Length:
      if (a < 0.01) return number(si * 1000) + "mm";
      if (a < 10) return number(si * 100) + "cm";
      return number(si) + "m";
    case Dimension::Angle: return number(si * 180 / std::numbers::pi) + "deg";
    case Dimension::Time: return a < 1 ? number(si * 1000) + "ms" : number(si) + "s";
    case Dimension::Speed: return number(si * 100) + "cm/s";
    case Dimension::Acceleration: return number(si) + "m/s^2";
    case Dimension::Mass: return a < 1 ? number(si * 1000) + "g" : number(si) + "kg";
    case Dimension::TurnRate: return number(si * 180 / std::numbers::pi) + "deg/s";
    case Dimension::TurnAcceleration: return number(si * 180 / std::numbers::pi) + "deg/s^2";
  }
  return number(si);
}

RuleMessage rule_message(const sim::Problem& p, const RuleContext& context) {
  switch (p.info().object) {
    case sim::Object::Arena: return arena_message(p, context);
    case sim::Object::Placement: return placement_message(p, context);
    case sim::Object::Robot: return robot_message(p, context);
  }
  return {p.message(), {}};
}

}  // namespace esc::compiler
