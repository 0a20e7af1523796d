#include "runtime/store/members_export.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "runtime/store/export.hpp"

namespace esc::store {

namespace {

struct MemberRow {
  const std::string& experiment;
  const std::string& condition;
  const StoredController& controller;
  const StoredMember& member;
};

bool of_kind(const StoredController& c, std::string_view kind) {
  return c.members && member_kind_name(c.members->layout.kind) == kind;
}

void for_each_row(const std::vector<StoredDirectory>& directories, std::string_view kind,
                  const std::function<void(const MemberRow&)>& f) {
  static const std::string kNone;
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments)
      for (const StoredController& c : e.controllers)
        if (of_kind(c, kind))
          for (const StoredMember& m : c.members->rows) f({e.name, e.condition ? e.condition->name : kNone, c, m});
}

// The value columns: every layout's names, in the order first met.
std::vector<std::string> value_columns(const std::vector<StoredDirectory>& directories, std::string_view kind) {
  std::vector<std::string> names;
  const auto add = [&](const std::string& n) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  for (const StoredDirectory& d : directories)
    for (const StoredExperiment& e : d.experiments)
      for (const StoredController& c : e.controllers)
        if (of_kind(c, kind)) {
          for (const std::string& n : c.members->layout.objectives) add(n);
          for (const std::string& n : c.members->layout.descriptors) add(n);
        }
  return names;
}

// The row's value of each column, or none.
std::vector<std::optional<double>> values(const MemberRow& r, const std::vector<std::string>& columns) {
  std::vector<std::optional<double>> v(columns.size());
  const eval::MemberLayout& l = r.controller.members->layout;
  const auto put = [&](const std::vector<std::string>& names, const std::vector<double>& x) {
    for (std::size_t i = 0; i < names.size() && i < x.size(); ++i)
      v[static_cast<std::size_t>(std::find(columns.begin(), columns.end(), names[i]) - columns.begin())] = x[i];
  };
  put(l.objectives, r.member.objectives);
  put(l.descriptors, r.member.descriptors);
  return v;
}

}  // namespace

std::string members_csv(const std::vector<StoredDirectory>& directories, std::string_view kind) {
  const std::vector<std::string> columns = value_columns(directories, kind);
  std::string out = "experiment,condition,controller,algorithm,run,generation,cell";
  for (const std::string& c : columns) {
    out += ',';
    out += csv_field(c);
  }
  out += "\n";
  for_each_row(directories, kind, [&](const MemberRow& r) {
    out += fmt::format("{},{},{},{},{},{},{}", r.experiment, csv_field(r.condition), r.controller.name,
                       r.controller.algorithm, r.member.run + 1, r.member.generation, r.member.cell);
    for (const std::optional<double>& v : values(r, columns)) out += v ? fmt::format(",{:.17g}", *v) : ",";
    out += "\n";
  });
  return out;
}

nlohmann::ordered_json members_json(const std::vector<StoredDirectory>& directories, std::string_view kind) {
  const std::vector<std::string> columns = value_columns(directories, kind);
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for_each_row(directories, kind, [&](const MemberRow& r) {
    nlohmann::ordered_json row = {{"experiment", r.experiment}, {"condition", r.condition},
                                  {"controller", r.controller.name}, {"algorithm", r.controller.algorithm},
                                  {"run", r.member.run + 1}, {"generation", r.member.generation},
                                  {"cell", r.member.cell}};
    const std::vector<std::optional<double>> v = values(r, columns);
    for (std::size_t i = 0; i < columns.size(); ++i)
      row[columns[i]] = v[i] && std::isfinite(*v[i]) ? nlohmann::ordered_json(*v[i]) : nlohmann::ordered_json();
    rows.push_back(std::move(row));
  });
  return rows;
}

}  // namespace esc::store
