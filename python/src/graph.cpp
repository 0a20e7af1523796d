// A NEAT network's graph genome between its flat form (what runs store and esc.evaluate
// takes; runtime/genome/graph/codec.hpp) and its nodes and links as arrays (esc.Network),
// both ways through the C++ codec, so that Python reads and writes exactly what a run does.
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "runtime/genome/graph/codec.hpp"

namespace esc::python {

namespace py = pybind11;
namespace gg = genome::graph;

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ids = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using Flags = py::array_t<bool, py::array::c_style | py::array::forcecast>;

py::dict decode_graph(const Doubles& flat) {
  if (flat.ndim() != 1) throw py::value_error("a graph genome is a 1-D array");
  gg::Graph g;
  if (std::string why = gg::decode(std::span<const double>(flat.data(), static_cast<std::size_t>(flat.size())), g);
      !why.empty())
    throw py::value_error("not a graph genome: " + why);
  std::vector<std::int64_t> ids, ins, outs, innovations;
  std::vector<std::string> kinds, activations;
  std::vector<double> weights;
  std::vector<bool> enabled;
  for (const gg::NodeGene& n : g.nodes) {
    ids.push_back(n.id);
    kinds.emplace_back(gg::kind_name(n.kind));
    activations.emplace_back(gg::activation_name(n.activation));
  }
  for (const gg::LinkGene& l : g.links) {
    ins.push_back(l.in);
    outs.push_back(l.out);
    weights.push_back(l.weight);
    enabled.push_back(l.enabled);
    innovations.push_back(l.innovation);
  }
  py::dict d;
  d["id"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(ids.size()), ids.data());
  d["kind"] = kinds;
  d["activation"] = activations;
  d["in"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(ins.size()), ins.data());
  d["out"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(outs.size()), outs.data());
  d["weight"] = py::array_t<double>(static_cast<py::ssize_t>(weights.size()), weights.data());
  py::array_t<bool> on(static_cast<py::ssize_t>(enabled.size()));
  for (std::size_t i = 0; i < enabled.size(); ++i) on.mutable_at(static_cast<py::ssize_t>(i)) = enabled[i];
  d["enabled"] = on;
  d["innovation"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(innovations.size()), innovations.data());
  return d;
}

template <class E, std::size_t N>
E by_name(const std::string& name, std::string_view (*name_of)(E), const char* what) {
  for (std::size_t i = 0; i < N; ++i)
    if (name_of(static_cast<E>(i)) == name) return static_cast<E>(i);
  throw py::value_error(std::string("unknown node ") + what + " `" + name + "`");
}

Doubles encode_graph(const Ids& ids, const std::vector<std::string>& kinds, const std::vector<std::string>& activations,
                     const Ids& ins, const Ids& outs, const Doubles& weights, const Flags& enabled,
                     const Ids& innovations) {
  const auto nodes = static_cast<std::size_t>(ids.size());
  const auto links = static_cast<std::size_t>(ins.size());
  if (kinds.size() != nodes || activations.size() != nodes)
    throw py::value_error("the nodes' id, kind and activation differ in length");
  if (static_cast<std::size_t>(outs.size()) != links || static_cast<std::size_t>(weights.size()) != links ||
      static_cast<std::size_t>(enabled.size()) != links || static_cast<std::size_t>(innovations.size()) != links)
    throw py::value_error("the links' in, out, weight, enabled and innovation differ in length");
  gg::Graph g;
  for (std::size_t i = 0; i < nodes; ++i)
    g.nodes.push_back({ids.at(static_cast<py::ssize_t>(i)),
                       by_name<gg::NodeKind, 4>(kinds[i], &gg::kind_name, "kind"),
                       by_name<gg::Activation, 4>(activations[i], &gg::activation_name, "activation")});
  for (std::size_t i = 0; i < links; ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    g.links.push_back({ins.at(k), outs.at(k), weights.at(k), enabled.at(k), innovations.at(k)});
  }
  if (std::string why = gg::misfit(g); !why.empty()) throw py::value_error("not a graph genome: " + why);
  const std::vector<double> flat = gg::encode(g);
  return Doubles(static_cast<py::ssize_t>(flat.size()), flat.data());
}

}  // namespace

void bind_graph(py::module_& m) {
  m.def("decode_graph", &decode_graph, py::arg("flat"),
        "A graph genome's nodes (id, kind, activation) and links (in, out, weight, enabled, innovation) as arrays; "
        "ValueError when `flat` is not one.");
  m.def("encode_graph", &encode_graph, py::arg("id"), py::arg("kind"), py::arg("activation"), py::arg("in_"),
        py::arg("out"), py::arg("weight"), py::arg("enabled"), py::arg("innovation"),
        "The flat form of a graph genome given as arrays; ValueError when they do not make one.");
}

}  // namespace esc::python
