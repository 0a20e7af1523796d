#include "runtime/report/trajectory_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "runtime/report/markup.hpp"

namespace esc::report {

namespace {

// The report page's colours (runtime/report/assets/report.js), so both read alike.
constexpr std::array<const char*, 10> kActionColours = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2",
                                                        "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
constexpr std::array<const char*, 10> kEpochColours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                                       "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
constexpr double kMargin = 20.0;        // SVG units are millimetres of the arena
constexpr double kTitleHeight = 46.0;
constexpr double kLegendWidth = 240.0;
constexpr double kLegendLine = 20.0;
constexpr const char* kObstacle = "#8d96a8";
constexpr const char* kGoal = "#c51b7d";
// A colour no behavior and no epoch takes (as on the report page).
constexpr const char* kCollision = "#111111";

// Arena metres to SVG units: x to the right, y up (SVG's y runs down).
struct Frame {
  double left = kMargin;
  double top = kMargin + kTitleHeight;
  double height_mm = 0.0;
  [[nodiscard]] double x(double x_m) const { return left + x_m * 1000.0; }
  [[nodiscard]] double y(double y_m) const { return top + height_mm - y_m * 1000.0; }
};

// [begin, end) of each epoch's steps.
std::vector<std::pair<std::size_t, std::size_t>> epoch_ranges(std::span<const eval::TraceStep> steps) {
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (i == 0 || steps[i].epoch != steps[i - 1].epoch) ranges.emplace_back(i, i + 1);
    else ranges.back().second = i + 1;
  return ranges;
}

// The colour of choice i of n: the palette for up to 10, else hues spread evenly at
// saturation 0.65 and lightness 0.45 (report.js's choiceColour), so 24 behaviors stay apart.
std::string choice_colour(std::size_t i, std::size_t n) {
  if (n <= kActionColours.size()) return kActionColours[i % kActionColours.size()];
  const double h = 360.0 * static_cast<double>(i) / static_cast<double>(n), s = 0.65, l = 0.45;
  const double a = s * std::min(l, 1.0 - l);
  const auto channel = [&](double k) {
    const double t = std::fmod(k + h / 30.0, 12.0);
    return static_cast<int>(std::lround(255.0 * (l - a * std::max(-1.0, std::min({t - 3.0, 9.0 - t, 1.0})))));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", channel(0), channel(8), channel(4));
}

std::size_t robots_of(const TrajectoryFigure& f) { return eval::trace_robots(f.steps); }

// A group's paths are coloured by robot; a robot alone's by the acting action or behavior, or
// by epoch for a classical head.
std::string colour_of(const TrajectoryFigure& f, const eval::TraceStep& t) {
  if (t.grouped) return choice_colour(static_cast<std::size_t>(t.robot), robots_of(f));
  if (!f.choices.empty() && t.action >= 0) return choice_colour(static_cast<std::size_t>(t.action), f.choices.size());
  return kEpochColours[static_cast<std::size_t>(t.epoch) % kEpochColours.size()];
}

void draw_arena(std::string& svg, const TrajectoryFigure& f, const Frame& at) {
  const sim::ArenaSpec& a = f.arena;
  svg += fmt::format(R"~(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="#fbfbf8" stroke="#333" stroke-width="3"/>)~"
                     "\n", at.x(0), at.y(a.height_m), a.width_m * 1000.0, a.height_m * 1000.0);
  for (const sim::CylinderObstacle& c : a.cylinders)
    svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" fill="{}"/>)~" "\n", at.x(c.center_m.x),
                       at.y(c.center_m.y), c.radius_m * 1000.0, kObstacle);
  // A segment wall is the rectangle the simulator holds for it.
  std::vector<sim::BoxObstacle> boxes = a.boxes;
  for (const sim::WallSegment& w : a.walls) boxes.push_back(sim::wall_box(w));
  for (const sim::BoxObstacle& b : boxes)
    svg += fmt::format(R"~(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="{}" transform="rotate({:.3f} {:.1f} {:.1f})"/>)~"
                       "\n", at.x(b.center_m.x) - b.size_m.x * 500.0, at.y(b.center_m.y) - b.size_m.y * 500.0,
                       b.size_m.x * 1000.0, b.size_m.y * 1000.0, kObstacle, -b.angle_rad * 180.0 / std::numbers::pi,
                       at.x(b.center_m.x), at.y(b.center_m.y));
  // The goal: a target of two rings.
  if (a.goal)
    svg += fmt::format(R"~(<circle cx="{0:.1f}" cy="{1:.1f}" r="9" fill="none" stroke="{2}" stroke-width="2"/><circle cx="{0:.1f}" cy="{1:.1f}" r="3.5" fill="{2}"/>)~"
                       "\n", at.x(a.goal->x), at.y(a.goal->y), kGoal);
}

// Zones where they were in each epoch drawn (random ones move at every epoch start), each
// place once, labelled with its epochs when the zone moves; lights, over the zones they follow.
void draw_zones_and_lights(std::string& svg, const TrajectoryFigure& f, const Frame& at) {
  std::set<std::tuple<std::size_t, double, double>> drawn;
  std::vector<std::tuple<std::size_t, sim::Vec2, std::string>> places;   // zone, where, epochs
  for (const auto& [begin, end] : epoch_ranges(f.steps)) {
    const eval::TraceStep& t = f.steps[begin];
    for (std::size_t z = 0; z < f.arena.zones.size(); ++z) {
      const sim::Vec2 c = z < t.zone_count ? t.zones[z] : f.arena.zones[z].center_m;
      if (drawn.emplace(z, c.x, c.y).second) places.emplace_back(z, c, "");
      for (auto& [zone, where, epochs] : places)
        if (zone == z && where.x == c.x && where.y == c.y)
          epochs += fmt::format("{}{}", epochs.empty() ? "" : ",", t.epoch + 1);
    }
  }
  for (const auto& [z, c, epochs] : places) {
    const sim::Zone& zone = f.arena.zones[z];
    const char* fill = zone.recharge ? "rgba(44,160,44,0.18)" : zone.visible ? "rgba(60,60,60,0.18)" : "rgba(60,60,60,0.06)";
    const std::string style = fmt::format(R"~(fill="{}" stroke="rgba(60,60,60,0.5)" stroke-dasharray="4 3")~", fill);
    if (zone.shape == sim::ZoneShape::Circle)
      svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" {}/>)~" "\n", at.x(c.x), at.y(c.y),
                         zone.radius_m * 1000.0, style);
    else
      svg += fmt::format(R"~(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" {}/>)~" "\n",
                         at.x(c.x) - zone.size_m.x * 500.0, at.y(c.y) - zone.size_m.y * 500.0, zone.size_m.x * 1000.0,
                         zone.size_m.y * 1000.0, style);
    // Under the zone, clear of a light above its centre.
    const double below = zone.shape == sim::ZoneShape::Circle ? zone.radius_m * 1000.0 : zone.size_m.y * 500.0;
    if (zone.random_position)
      svg += fmt::format(R"~(<text x="{:.1f}" y="{:.1f}" font-size="10" fill="#555" text-anchor="middle">epoch {}</text>)~"
                         "\n", at.x(c.x), at.y(c.y) + below + 11.0, epochs);
  }
  for (const sim::LightSource& l : f.arena.lights) {
    std::vector<sim::Vec2> where;
    if (l.above_zone < 0) where.push_back(l.position_m);
    for (const auto& [z, c, epochs] : places)
      if (static_cast<int>(z) == l.above_zone) where.push_back(c);
    for (const sim::Vec2& p : where)
      svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="7" fill="#f2c12e" stroke="#a67c00" stroke-width="1.5"/>)~"
                         "\n", at.x(p.x), at.y(p.y));
  }
}

// Where colours name behaviors, epochs drawn from one fixed start would lie on each other
// indistinguishably: each epoch has its own dash pattern (solid for the first), in the legend.
constexpr std::array<const char*, 4> kEpochDashes = {"", "9 4", "2 4", "12 4 2 4"};

bool dashed_epochs(const TrajectoryFigure& f) {
  return (!f.choices.empty() || robots_of(f) > 1) && epoch_ranges(f.steps).size() > 1;
}

std::string dash_of(const TrajectoryFigure& f, int epoch) {
  const char* dash = kEpochDashes[static_cast<std::size_t>(epoch) % kEpochDashes.size()];
  return dashed_epochs(f) && *dash != '\0' ? fmt::format(R"~( stroke-dasharray="{}")~", dash) : std::string();
}

// Where a robot's epoch starts (a small circle numbered with the epoch) and ends (the robot,
// with its heading, numbered too; a group's robot filled with its colour).
void draw_epoch_ends(std::string& svg, const TrajectoryFigure& f, const Frame& at, const eval::TraceStep& first,
                     const eval::TraceStep& last) {
  static const TrajectoryFigure::Body kPoint;
  const TrajectoryFigure::Body& b =
      f.bodies.empty() ? kPoint : f.bodies[std::min(static_cast<std::size_t>(last.robot), f.bodies.size() - 1)];
  const double r_mm = b.radius_m * 1000.0;
  svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="4" fill="#fff" stroke="#1d2330" stroke-width="1.5"/>)~"
                     "\n" R"~(<text x="{:.1f}" y="{:.1f}" font-size="11" fill="#1d2330">{}</text>)~" "\n",
                     at.x(first.pose.x_m), at.y(first.pose.y_m), at.x(first.pose.x_m) + 6.0, at.y(first.pose.y_m) - 6.0,
                     first.epoch + 1);
  const double x = at.x(last.pose.x_m);
  const double y = at.y(last.pose.y_m);
  const std::string body =
      last.grouped ? fmt::format(R"~(fill="{}" fill-opacity="0.35" stroke="#1d2330" stroke-width="1.5")~", colour_of(f, last))
                   : std::string(R"~(fill="rgba(31,119,180,0.2)" stroke="#1d2330" stroke-width="1.5")~");
  if (b.outline_m.empty()) {
    svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" {}/>)~" "\n", x, y, r_mm, body);
  } else {
    const double c = std::cos(last.pose.heading_rad), s = std::sin(last.pose.heading_rad);
    std::string points;
    for (const sim::Vec2& v : b.outline_m)
      points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", at.x(last.pose.x_m + c * v.x - s * v.y),
                            at.y(last.pose.y_m + s * v.x + c * v.y));
    svg += fmt::format(R"~(<polygon points="{}" {}/>)~" "\n", points, body);
  }
  svg += fmt::format(R"~(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="#1d2330" stroke-width="1.5"/>)~"
                     "\n" R"~(<text x="{:.1f}" y="{:.1f}" font-size="11" fill="#1d2330">{}</text>)~" "\n",
                     x, y, x + r_mm * std::cos(last.pose.heading_rad), y - r_mm * std::sin(last.pose.heading_rad),
                     x + r_mm + 3.0, y + r_mm + 8.0, last.epoch + 1);
}

// Each epoch's path of each robot (a group's rows hold every robot of a step, in robot
// order), one <path> per stretch with the same colour; its start (a small circle numbered
// with the epoch), its end (the robot, with its heading, numbered too) and its collisions.
void draw_paths(std::string& svg, const TrajectoryFigure& f, const Frame& at) {
  const std::size_t robots = robots_of(f);
  svg += R"~(<g fill="none" stroke-width="2" stroke-linejoin="round" stroke-linecap="round">)~" "\n";
  for (const auto& [begin, end] : epoch_ranges(f.steps))
    for (std::size_t r = 0; r < robots; ++r) {
      std::string d;
      std::string colour;
      const std::string dash = dash_of(f, f.steps[begin].epoch);
      for (std::size_t i = begin + r + robots; i < end; i += robots) {
        const std::string c = colour_of(f, f.steps[i]);
        if (c != colour) {
          if (!colour.empty()) svg += fmt::format(R"~(<path stroke="{}"{} d="{}"/>)~" "\n", colour, dash, d);
          colour = c;
          d = fmt::format("M{:.1f} {:.1f}", at.x(f.steps[i - robots].pose.x_m), at.y(f.steps[i - robots].pose.y_m));
        }
        d += fmt::format(" L{:.1f} {:.1f}", at.x(f.steps[i].pose.x_m), at.y(f.steps[i].pose.y_m));
      }
      if (!colour.empty()) svg += fmt::format(R"~(<path stroke="{}"{} d="{}"/>)~" "\n", colour, dash, d);
    }
  svg += "</g>\n";
  for (const eval::TraceStep& t : f.steps)
    if (t.collided)
      svg += fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="3" fill="{}"/>)~" "\n", at.x(t.pose.x_m), at.y(t.pose.y_m),
                         kCollision);
  for (const auto& [begin, end] : epoch_ranges(f.steps))
    for (std::size_t r = 0; r < robots && begin + r < end; ++r)
      draw_epoch_ends(svg, f, at, f.steps[begin + r], f.steps[end - robots + r]);
}

// A bar of a round length under the arena's lower left corner: the drawing is to scale.
// Returns the height it takes.
double draw_scale_bar(std::string& svg, const TrajectoryFigure& f, const Frame& at) {
  const double width_mm = f.arena.width_m * 1000.0;
  double length_mm = 1.0;
  for (const double step : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0})
    if (step <= width_mm / 4.0) length_mm = step;
  const double x = at.x(0.0), y = at.y(0.0) + 14.0;
  svg += fmt::format(R"~(<g stroke="#1d2330" stroke-width="1.5"><line x1="{0:.1f}" y1="{1:.1f}" x2="{2:.1f}" y2="{1:.1f}"/>)~"
                     R"~(<line x1="{0:.1f}" y1="{3:.1f}" x2="{0:.1f}" y2="{4:.1f}"/><line x1="{2:.1f}" y1="{3:.1f}" x2="{2:.1f}" y2="{4:.1f}"/></g>)~"
                     "\n" R"~(<text x="{5:.1f}" y="{6:.1f}" font-size="11" fill="#1d2330">{7}</text>)~" "\n",
                     x, y, x + length_mm, y - 4.0, y + 4.0, x + length_mm + 6.0, y + 4.0,
                     length_mm >= 1000.0 ? fmt::format("{:g} m", length_mm / 1000.0)
                                         : length_mm >= 10.0 ? fmt::format("{:g} cm", length_mm / 10.0)
                                                             : fmt::format("{:g} mm", length_mm));
  return 24.0;
}

// What each colour and mark means; returns the legend's height.
double draw_legend(std::string& svg, const TrajectoryFigure& f, double left, double top) {
  std::vector<std::pair<std::string, std::string>> colours;   // colour, label
  const std::size_t robots = robots_of(f);
  if (robots > 1) {
    std::vector<std::size_t> collisions(robots, 0);
    for (const eval::TraceStep& t : f.steps) collisions[static_cast<std::size_t>(t.robot)] += t.collided ? 1 : 0;
    for (std::size_t r = 0; r < robots; ++r)
      colours.emplace_back(choice_colour(r, robots), fmt::format("robot {} ({} collision step{})", r + 1, collisions[r],
                                                                 collisions[r] == 1 ? "" : "s"));
  } else if (!f.choices.empty()) {
    std::vector<std::size_t> steps(f.choices.size(), 0);
    for (const eval::TraceStep& t : f.steps)
      if (t.action >= 0 && static_cast<std::size_t>(t.action) < steps.size()) ++steps[static_cast<std::size_t>(t.action)];
    for (std::size_t i = 0; i < f.choices.size(); ++i)
      colours.emplace_back(choice_colour(i, f.choices.size()),
                           fmt::format("{} ({:.0f}% of steps)", f.choices[i],
                                       f.steps.empty() ? 0.0 : 100.0 * static_cast<double>(steps[i]) /
                                                                    static_cast<double>(f.steps.size())));
  } else {
    for (const auto& [begin, end] : epoch_ranges(f.steps))
      colours.emplace_back(kEpochColours[static_cast<std::size_t>(f.steps[begin].epoch) % kEpochColours.size()],
                           fmt::format("epoch {} ({} steps)", f.steps[begin].epoch + 1, end - begin));
  }
  double y = top;
  svg += fmt::format(R"~(<g class="legend" font-size="13" fill="#1d2330">)~" "\n"
                     R"~(<text x="{:.1f}" y="{:.1f}" font-weight="bold">{}</text>)~" "\n",
                     left, y, robots > 1 ? "path, by robot" : f.choices.empty() ? "path, by epoch" : "path, by acting behavior");
  for (const auto& [colour, label] : colours) {
    y += kLegendLine;
    svg += fmt::format(R"~(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="3"/>)~"
                       R"~(<text x="{:.1f}" y="{:.1f}">{}</text>)~" "\n",
                       left, y - 4.0, left + 24.0, y - 4.0, colour, left + 32.0, y, escape_markup(label));
  }
  if (dashed_epochs(f)) {
    y += kLegendLine * 1.5;
    svg += fmt::format(R"~(<text x="{:.1f}" y="{:.1f}" font-weight="bold">path, by epoch</text>)~" "\n", left, y);
    for (const auto& [begin, end] : epoch_ranges(f.steps)) {
      y += kLegendLine;
      const int epoch = f.steps[begin].epoch;
      svg += fmt::format(R"~(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="#1d2330" stroke-width="2"{}/>)~"
                         R"~(<text x="{:.1f}" y="{:.1f}">epoch {} ({} steps)</text>)~" "\n",
                         left, y - 4.0, left + 24.0, y - 4.0, dash_of(f, epoch), left + 32.0, y, epoch + 1,
                         (end - begin) / robots);
    }
  }
  y += kLegendLine * 1.5;
  const auto mark = [&](const std::string& symbol, std::string_view label) {
    svg += symbol + fmt::format(R"~(<text x="{:.1f}" y="{:.1f}">{}</text>)~" "\n", left + 32.0, y, label);
    y += kLegendLine;
  };
  const double cx = left + 12.0;
  mark(fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="4" fill="#fff" stroke="#1d2330" stroke-width="1.5"/>)~", cx, y - 4.0),
       "start of an epoch (its number)");
  mark(fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="7" fill="rgba(31,119,180,0.2)" stroke="#1d2330" stroke-width="1.5"/>)~",
                   cx, y - 4.0), "robot at the end, heading, epoch");
  mark(fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="3" fill="{}"/>)~", cx, y - 4.0, kCollision), "collision");
  mark(fmt::format(R"~(<rect x="{:.1f}" y="{:.1f}" width="14" height="10" fill="{}"/>)~", cx - 7.0, y - 9.0, kObstacle),
       "wall or obstacle");
  if (!f.arena.zones.empty())
    mark(fmt::format(R"~(<rect x="{:.1f}" y="{:.1f}" width="14" height="10" fill="rgba(44,160,44,0.18)" stroke="rgba(60,60,60,0.5)" stroke-dasharray="4 3"/>)~",
                     cx - 7.0, y - 9.0), "floor zone (green: recharge)");
  if (!f.arena.lights.empty())
    mark(fmt::format(R"~(<circle cx="{:.1f}" cy="{:.1f}" r="6" fill="#f2c12e" stroke="#a67c00" stroke-width="1.5"/>)~", cx, y - 4.0),
         "light");
  if (f.arena.goal)
    mark(fmt::format(R"~(<circle cx="{0:.1f}" cy="{1:.1f}" r="6" fill="none" stroke="{2}" stroke-width="2"/><circle cx="{0:.1f}" cy="{1:.1f}" r="2.5" fill="{2}"/>)~",
                     cx, y - 4.0, kGoal),
         "goal");
  svg += "</g>\n";
  return y - top;
}

}  // namespace

std::string trajectory_svg(const TrajectoryFigure& f) {
  Frame at;
  at.height_mm = f.arena.height_m * 1000.0;
  std::string body;
  draw_arena(body, f, at);
  draw_zones_and_lights(body, f, at);
  draw_paths(body, f, at);
  const double scale_bar = draw_scale_bar(body, f, at);
  const double legend_left = at.x(f.arena.width_m) + 2.0 * kMargin;
  const double legend_height = draw_legend(body, f, legend_left, at.top + 10.0);
  const double width = legend_left + kLegendWidth + kMargin;
  const double height = std::max(at.top + at.height_mm + scale_bar, at.top + 10.0 + legend_height) + kMargin;
  return fmt::format(R"~(<?xml version="1.0" encoding="UTF-8"?>)~" "\n"
                     R"~(<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{0:.0f}" height="{1:.0f}" viewBox="0 0 {0:.0f} {1:.0f}" font-family="sans-serif">)~" "\n"
                     R"~(<rect width="100%" height="100%" fill="#fff"/>)~" "\n"
                     R"~(<text x="{2:.1f}" y="{3:.1f}" font-size="16" font-weight="bold" fill="#1d2330">{4}</text>)~" "\n"
                     R"~(<text x="{2:.1f}" y="{5:.1f}" font-size="12" fill="#555">{6}</text>)~" "\n"
                     "{7}</svg>\n",
                     width, height, kMargin, kMargin + 14.0, escape_markup(f.title), kMargin + 32.0, escape_markup(f.subtitle), body);
}

}  // namespace esc::report
