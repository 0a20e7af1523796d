#pragma once
// What the compiler produces for a `controller` declaration: the network's shape and its
// head. The genome is the flat vector of the network's weights; genome_size() says how long.
// A GP tree controller (`tree(...)`) has primitives instead of a network: its genome is a
// tree (runtime/genome/tree), run by tree_control::TreeDriver.
#include <cstddef>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "runtime/control/behavior.hpp"
#include "runtime/expr/observables.hpp"

// Only a pointer is held here: the tree genome (esc_genome_tree) needs nothing of esc_control,
// and the controllers that run trees (esc_tree_control) build on both.
namespace esc::genome::tree {
class PrimitiveSet;
}

namespace esc::control {

enum class Activation { Tanh, Sigmoid, Linear };

// Mlp: feed-forward, any number of hidden layers (possibly none).
// Elman: exactly one hidden layer, fully connected to itself with a one-step delay
// (Godzik et al. 2003, footnote on Elman networks):
//   h_t = act(W_in [1; x_t] + W_ctx h_{t-1}),   y_t = act_out(W_out [1; h_t]),
// with the context h_{-1} = 0 after every reset() (start of each epoch).
// Graph: NEAT's network (`neat(...)`), no hidden layers declared: its genome is a graph
// genome (runtime/genome/graph) whose topology evolves, of no fixed size; run by GraphNet.
enum class NetworkKind { Mlp, Elman, Graph };

// A network: inputs are frame slots, then hidden layers, then outputs.
// Each layer's weights are stored neuron by neuron, bias first, then one weight per input;
// an Elman hidden neuron then has one context weight per hidden neuron (the previous
// step's activations, in neuron order). So, with n inputs, hidden sizes h_1..h_L and o
// outputs:
//   Mlp:   sum_l h_l (1 + h_{l-1}) + o (1 + h_L),   h_0 = n
//   Elman: h (1 + n + h) + o (1 + h)                 (17-5-2: 5*23 + 2*6 = 127)
struct MlpSpec {
  std::vector<expr::Slot> inputs;
  std::vector<int> hidden;          // sizes of the hidden layers; Elman: exactly one
  Activation hidden_activation = Activation::Tanh;
  NetworkKind kind = NetworkKind::Mlp;
};

// Classical head: two outputs in [-1, 1] (tanh) are the wheel commands.
// Symbolic head: outputs in [0, 1] (logistic). The first n (one per action) choose the
// action by argmax (first wins a tie); then each action's parameters follow in order
// (action 0's, then action 1's, ...), so n actions of one parameter give 2n outputs.
// Supervisor head: one output in [0, 1] (logistic) per supervised behavior; the argmax
// (first wins a tie) names the behavior that computes this step's wheel command.
enum class Head { Classical, Symbolic, Supervisor };

struct ControllerSpec;

// A hand-written behavior run with constant arguments, e.g. `forward(0.8)`: the arguments
// are written into frame[slot::param + k] before its wheel programs run.
struct BehaviorCall {
  Behavior behavior;
  std::vector<double> args;         // exactly one per behavior.params
};

// An evolved controller frozen with fixed weights (typically another experiment's best
// genome): classical, symbolic, or itself a supervisor; MLP or Elman.
struct FixedController {
  std::shared_ptr<const ControllerSpec> spec;
  std::vector<double> genome;       // exactly spec->genome_size() values (a graph genome: any)
};

struct SupervisedBehavior {
  std::string name;                 // for usage tables, e.g. "avoid"
  std::variant<BehaviorCall, FixedController> what;
};

// One action (symbolic head) or behavior (supervisor) of a controller, as scripts, usage
// tables and reports name it; the compiler fills them in ControllerSpec::choices.
struct Choice {
  std::string name;       // the usage table's name without arguments: `avoid`, `crash_2`, `forward`
  std::string behavior;   // the behavior declared: `useless.crash`, `forward`
  std::string library;    // the library it comes from, "" when none
  bool useless = false;   // its library is marked `useless`: reports draw it apart
  // Experiment-wide: written into the frame's `acting` slot on every step it acts, so that
  // one fitness program reads `using(B)` for every compared controller. -1: none.
  int id = -1;
};

struct ControllerSpec {
  std::string name;
  MlpSpec mlp;
  Head head = Head::Classical;
  std::vector<Behavior> actions;               // Symbolic head only
  std::vector<SupervisedBehavior> behaviors;   // Supervisor head only
  // Set for a tree controller, whose head says what the tree returns: Classical a Wheels
  // tree (both wheel commands), Symbolic an Action tree (one of `actions`, with its
  // parameters), Supervisor a Behavior tree (one of `behaviors`). `mlp` is then unused.
  // Shared and immutable: copies of the spec share one set.
  std::shared_ptr<const genome::tree::PrimitiveSet> primitives;
  std::string primitives_name;                 // the script's `primitives` declaration
  // The algorithm a compared controller's `by` names (evo::Algorithm::name); empty: the
  // experiment's default for its kind (ExperimentSpec::evolution_of).
  std::string evolved_by;
  // One per choice_names() entry, in order, when the compiler built the spec; may be empty
  // (then no choice has an id: `using(B)` reads 0).
  std::vector<Choice> choices;
  // A controller per body (`per_body(khepera: cc, thymio2: ct)`), for a group whose bodies
  // read other sensors: `networks` holds each body's network controller (inputs read on that
  // body), in the declaration's order, their weights one after the other in the genome, and
  // `network_bodies` the body each is for. `mlp`, the head, the actions or behaviors and
  // `choices` are the first network's: every network has the same head and choices, so the
  // group's usage counts one set of them. `body_networks[b]` is the network driving body b
  // of the experiment's group (ExperimentSpec::bodies; one entry for a group of one body),
  // filled where the experiment binds it. All empty for any other controller.
  std::vector<ControllerSpec> networks;
  std::vector<std::string> network_bodies;
  std::vector<std::size_t> body_networks;

  [[nodiscard]] bool per_body() const noexcept { return !networks.empty(); }
  // Where network k's weights start in a genome of this controller (per_body()).
  [[nodiscard]] std::size_t network_offset(std::size_t k) const noexcept;
  [[nodiscard]] bool is_tree() const noexcept { return primitives != nullptr; }
  // A `neat(...)` network: its genome is a graph genome, of no fixed size.
  [[nodiscard]] bool is_graph() const noexcept { return !is_tree() && mlp.kind == NetworkKind::Graph; }
  // Classical: 2. Symbolic: actions + all their parameters. Supervisor: behaviors.
  [[nodiscard]] int output_count() const noexcept;
  // The supervisor's genome is its own network only; sub-controllers' weights are fixed.
  // 0 for a tree or graph controller: neither has a fixed size.
  [[nodiscard]] std::size_t genome_size() const noexcept;
  // "8-14-6" style architecture string for tables; an Elman hidden layer is marked with
  // an r (recurrent): "17-5r-2". A supervisor's string is its own network's: "17-5r-4".
  // A tree controller: "tree wheels", "tree actions" or "tree behaviors". A NEAT network:
  // "17-neat-2". A controller per body: each body and its network's, in the declaration's
  // order (its genome's): "khepera 8-4-2 / thymio2 7-4-2".
  [[nodiscard]] std::string architecture() const;
  // The head as the results store and its tables name it: "classical", "symbolic",
  // "supervisor", or "tree" for a tree controller.
  [[nodiscard]] const char* head_name() const noexcept;
  // What Controller::usage() counts, in index order: the action names (Symbolic), the
  // behavior names (Supervisor), nothing (Classical).
  [[nodiscard]] std::vector<std::string> choice_names() const;
  // The experiment-wide id of choice `i` (Choice::id), -1 for none or an index out of range.
  [[nodiscard]] int choice_id(int i) const noexcept {
    return i >= 0 && static_cast<std::size_t>(i) < choices.size() ? choices[static_cast<std::size_t>(i)].id : -1;
  }
};

}  // namespace esc::control
