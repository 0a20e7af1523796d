#pragma once
// The abstract syntax of a script, built from the ANTLR parse tree by parse.cpp. Only the
// compiler sees it; it keeps every location for diagnostics. Values are as written (units
// are resolved by the checks, not here).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace esc::compiler::ast {

struct Name {
  std::string text;          // empty when the parser had to invent it (syntax error)
  SourceRange where;
};

// A number as written, with its optional unit: `60cm`, `-1`, `0.5 m/s^2`, `150`.
struct Quantity {
  double value = 0.0;        // sign applied, unit not applied
  std::string text;          // the number (with sign) as written
  std::string unit;          // "" when none
  SourceRange where;         // the whole quantity
  SourceRange unit_where;
  bool finite = true;        // false when the number overflowed a double (reported)
};

struct Expr {
  enum class Kind { Number, Bool, Name, Index, Call, Unary, Binary, If, Error };
  Kind kind = Kind::Error;
  std::string text;          // name (`library.member` too), function, or operator ("+", "and", "neg", ...)
  double number = 0.0;       // Number (unit not applied) and Bool
  std::string unit;          // Number
  SourceRange unit_where;
  std::vector<std::unique_ptr<Expr>> args;
  SourceRange where;         // first line of the expression; length clipped to that line
};
using ExprPtr = std::unique_ptr<Expr>;

// One parenthesised group of a list: `(68deg, 90deg)`.
struct QuantityTuple {
  std::vector<Quantity> items;
  SourceRange where;
};

// A setting's value as written, in a script or after `esc run --set KEY=`: `50ms`, `3`, `on`,
// a word (`comma`), a range `[-1, 1]`, a list or a list of tuples.
struct Value {
  enum class Kind { Quantity, Bool, Word, Range, List, Tuples } kind = Kind::Quantity;
  Quantity q;                // Quantity; Range: the lower bound
  Quantity hi;               // Range: the upper bound
  std::vector<Quantity> list;   // List (`[90deg, 0deg, -90deg]`, also `[]`)
  std::vector<QuantityTuple> tuples;   // Tuples (`[(68deg, 90deg), (43deg, 45deg)]`)
  bool flag = false;         // Bool (`on`, `true`)
  std::string text;          // as written (Word: the word)
  SourceRange where;
};

struct Setting {
  Name key;
  Value value;
};

struct Import {
  std::string path;          // unescaped
  SourceRange where;         // the string literal
};

struct DeclHead {
  Name name;
  SourceRange keyword;
  bool poisoned = false;     // holds a syntax error: not checked, references to it accepted
  int order = 0;             // position in the file
};

struct Cylinder {
  Quantity x, y, radius;
  SourceRange where;
};
struct Block {
  Quantity x, y, w, h;
  std::optional<Quantity> angle;
  SourceRange where;
};
struct Wall {                       // `wall from (X1, Y1) to (X2, Y2) [thickness T]`
  Quantity x1, y1, x2, y2;
  std::optional<Quantity> thickness;
  SourceRange where;
};
struct Goal {                       // `goal at (X, Y)`
  Quantity x, y;
  SourceRange where;
};
struct Start {
  bool random = true;
  Quantity x, y;
  std::optional<Quantity> heading;
  SourceRange where;
};
struct ArenaSize {
  Quantity w, h;
  SourceRange where;
};

struct Light {
  Name name;
  std::optional<Quantity> x, y;     // `at (x, y)`
  std::optional<Name> above;        // `above ZONE`
  std::optional<Quantity> height, intensity;
  SourceRange where;
};
struct Zone {
  Name name;
  bool circle = true;
  Quantity radius, w, h;
  bool random = false;
  Quantity x, y;                    // when !random
  std::vector<Name> flags;          // visible / invisible / recharge
  SourceRange where;
};
struct ArenaLength {                // `sweep_cell 4cm`, `reach_radius 5cm`
  Quantity value;
  SourceRange where;
};

struct ArenaDecl : DeclHead {
  std::vector<Light> lights;
  std::vector<Zone> zones;
  std::vector<ArenaLength> sweep_cells;    // more than one is an error
  std::vector<ArenaLength> reach_radii;    // more than one is an error
  std::vector<ArenaSize> sizes;     // more than one is an error
  std::vector<Cylinder> cylinders;
  std::vector<Block> blocks;
  std::vector<Wall> walls;
  std::vector<Goal> goals;          // more than one is an error
  std::vector<Start> starts;        // more than one is an error
};

struct RobotDecl : DeclHead {
  std::optional<Name> base;
  std::vector<Setting> settings;
};

struct BehaviorDecl : DeclHead {
  // A member of `library L { ... }`: name.text is `L.member`; `member` is the bare name.
  std::string library, member;
  bool useless = false;             // its library is marked `useless`
  // `behavior avoid = evolved from experiment E controller C`: no parameters or body.
  bool evolved = false;
  Name from_experiment, from_controller;
  std::vector<Name> params;
  Name body_fn;                     // `wheels`
  std::vector<ExprPtr> body_args;
  SourceRange body_where;
  std::vector<std::string> body_text;   // source text of each argument
};

struct LibraryDecl : DeclHead {
  std::vector<std::string> members;   // qualified names (`L.member`), in order
  std::optional<Name> mark;           // the word after the name: `useless` (checked by the lowering)
};

struct FitnessTerm {
  ExprPtr expr;
  std::string text;                 // source text, for resolved settings
  SourceRange where;                // the `step` or `stop` keyword
};

// `over robots min`: how a group's robots' terms make the group's.
struct FitnessOver {
  Name what;                        // `robots`
  Name reduce;                      // mean, sum, min, max
  SourceRange where;
};

struct FitnessDecl : DeclHead {
  std::vector<FitnessTerm> steps;   // more than one is an error
  std::vector<FitnessTerm> stops;
  std::vector<FitnessTerm> epoch_ends;        // `epoch:`, at most one
  std::vector<FitnessTerm> evaluation_ends;   // `evaluation:`, at most one
  std::vector<FitnessOver> overs;             // `over robots R`, at most one
};

struct Input {
  Name name;
  std::optional<Quantity> lo, hi;   // `ir[3]`: lo only; `ir[0..7]`: both
  SourceRange where;
};
struct Layer {
  Name word;                        // `hidden`, `wheels`
  std::optional<Quantity> size;
  SourceRange where;
};

// `forward(0.5)` in a supervisor's behavior list.
struct SupervisedRef {
  Name name;
  std::vector<Quantity> args;
  SourceRange where;
};

struct ControllerDecl : DeclHead {
  bool symbolic = false;
  bool supervisor = false;
  bool elman = false;
  bool neat = false;   // `neat(...)`: NEAT's network, no hidden layers
  // `tree(RESULT, primitives P)`: a GP tree instead of a network. RESULT is `wheels`
  // (tree_result), `actions [...]` (symbolic) or `behaviors [...]` (supervisor).
  bool tree = false;
  Name tree_result;
  Name primitives;
  std::vector<SupervisedRef> behaviors;
  SourceRange kind_where;
  std::vector<Input> inputs;
  std::vector<Layer> layers;
  std::vector<Name> actions;
  // `per_body(khepera: cc, ...)`: each body's name and its network controller's; empty for
  // any other controller.
  struct BodyNetwork {
    Name body, controller;
  };
  std::vector<BodyNetwork> per_body;
};

// ---- primitive sets: `primitives NAME { functions ... terminals ... }` ----------------
struct PrimFunction {
  std::string text;                 // "+", "min", "if", ...
  SourceRange where;
};
struct PrimTerminal {
  enum class Kind { Observable, Erc, Constant, Bool };
  Kind kind = Kind::Observable;
  Name name;                        // Observable; Erc: the word `erc`
  std::optional<Quantity> lo, hi;   // Observable: `ir[3]` lo only, `ir[0..7]` both; Erc: the range
  Quantity value;                   // Constant
  bool flag = false;                // Bool
  SourceRange where;
};
struct PrimitivesDecl : DeclHead {
  std::vector<PrimFunction> functions;
  std::vector<PrimTerminal> terminals;
};

struct EsOption {
  Name name;
  std::optional<Quantity> value;
  std::optional<Quantity> lo, hi;   // `bounds [lo, hi]`
  SourceRange where;
};

// `in [lo, hi]`: the range an objective's or a descriptor's values lie in.
struct DeclaredRange {
  Quantity lo, hi;
  SourceRange where;
};

// A group's body after the first (`robot khepera x 2, lit_khepera x 3`): its robot, inline
// settings and count (1 when not given).
struct GroupMember {
  Name ref;
  std::vector<Setting> settings;
  std::optional<Quantity> count;
};

struct ExpItem {
  enum class Kind {
    Arena, Robot, Epochs, Steps, Fitness, Objective, Descriptor, Success, StopAtSuccess, Evolve, Runs, Seed, Compare,
    StartFrom, Formation, Roles
  };
  Kind kind = Kind::Arena;
  SourceRange where;                // the keyword
  std::vector<Name> refs;           // arena/robot/fitness/evolve method/compare list
  // Compare: the name each controller of `refs` is compared under (`CS8 as CS`: `CS`);
  // empty text when it keeps its own.
  std::vector<Name> aliases;
  // Compare: the algorithm `by` names for controller `refs[i]`; empty text when none.
  std::vector<Name> algorithms;
  std::vector<Setting> settings;    // robot { ... } overrides
  std::vector<GroupMember> members;   // Robot: the group's further bodies, in order
  std::vector<Quantity> numbers;    // epochs [, steps] / steps / runs / seed / success's threshold / formation's spacing / roles
  std::optional<Value> list;        // Formation: `at [(x, y, heading), ...]`
  std::vector<EsOption> options;    // evolve es(...)
  std::optional<Quantity> generations;
  bool evaluate_only = false;       // StartFrom: `evaluate from ...` rather than `start from ...`
  // Fitness, Objective, Descriptor: `in [lo, hi]`.
  std::optional<DeclaredRange> range;
  bool minimize = false;            // Objective: `minimize`
  // Descriptor: its name is refs[0]; the expression, its text, `evaluation:` and `by WORD`
  // (shared: items are copied, an option list with its item).
  std::shared_ptr<const Expr> expr;
  std::string text;
  bool at_evaluation = false;
  Name reduce;
  std::vector<FitnessOver> overs;   // Descriptor: `over robots R`, at most one
  // Success: `success when refs[0] CMP numbers[0]`; the comparison as written (`<=`) and where.
  std::string compare;
  SourceRange compare_where;

  // Compare: the name controller `refs[i]` is compared under, its alias or its own.
  [[nodiscard]] const Name& compared_as(std::size_t i) const {
    return i < aliases.size() && !aliases[i].text.empty() ? aliases[i] : refs[i];
  }
};

struct ExperimentDecl : DeclHead {
  std::vector<ExpItem> items;
};

// The controllers an experiment compares: the declaration each names and the name it is
// compared (stored, reported, depended on) under.
struct Compared {
  const Name* controller;           // the controller declaration's name, as written
  const Name* name;                 // the alias when given, else `controller`
};
[[nodiscard]] inline std::vector<Compared> compared(const ExperimentDecl& d) {
  std::vector<Compared> out;
  for (const ExpItem& item : d.items)
    if (item.kind == ExpItem::Kind::Compare)
      for (std::size_t i = 0; i < item.refs.size(); ++i) out.push_back({&item.refs[i], &item.compared_as(i)});
  return out;
}

// ---- studies: `study NAME { conditions ... condition ... sweep ... runs N seed N }` -----
// A setting's value in a study: one value, or a list `[a, b, ...]` (a sweep's values; a
// range is a list of two numbers).
struct StudyValue {
  Value value;                      // when !list: a Quantity, Bool or Word
  bool list = false;
  std::vector<StudyValue> items;
  SourceRange where;
  std::string text;                 // as written
};

struct StudySetting {
  Name key;                         // a `--set` key: `robot.time_constant`, `mu`
  StudyValue value;
};

struct StudyItem {
  enum class Kind { Conditions, Condition, Sweep, Runs, Seed };
  Kind kind = Kind::Conditions;
  SourceRange where;                // the keyword
  Name name;                        // Condition: the condition's name
  std::vector<Name> experiments;    // Conditions: each; Condition and Sweep: the one
  std::vector<StudySetting> settings;   // Condition, Sweep
  std::optional<Quantity> number;   // Runs, Seed
};

struct StudyDecl : DeclHead {
  std::vector<StudyItem> items;
};

struct Module {
  std::filesystem::path file;       // as displayed in diagnostics
  std::vector<Import> imports;
  std::vector<ArenaDecl> arenas;
  std::vector<RobotDecl> robots;
  std::vector<BehaviorDecl> behaviors;
  std::vector<FitnessDecl> fitnesses;
  std::vector<ControllerDecl> controllers;
  std::vector<ExperimentDecl> experiments;
  std::vector<LibraryDecl> libraries;
  std::vector<PrimitivesDecl> primitives;
  std::vector<StudyDecl> studies;
  bool syntax_ok = true;
};

}  // namespace esc::compiler::ast
