#pragma once
// The extension module esc._esc, bound part by part, one file per part of the API: module.cpp
// calls each in turn. The Python package (python/esc) wraps these in the public API, and a
// new part (esc.run, ...) is one more file and one more call here.
#include <pybind11/pybind11.h>

namespace esc::python {

void bind_errors(pybind11::module_& m);     // errors.cpp: store errors as esc.Error
void bind_limits(pybind11::module_& m);     // limits.cpp: the ranges the esc program checks
void bind_script(pybind11::module_& m);     // script.cpp: compiling scripts
void bind_results(pybind11::module_& m);    // results.cpp: reading run directories
void bind_evaluate(pybind11::module_& m);   // evaluate.cpp: fitness of genomes
void bind_env(pybind11::module_& m);        // env.cpp: one epoch step by step
void bind_policy(pybind11::module_& m);     // policy.cpp: a genome's network as Env's policy
void bind_run(pybind11::module_& m);        // run.cpp: running and resuming experiments and studies
void bind_graph(pybind11::module_& m);      // graph.cpp: a NEAT network's genome as arrays and back

}  // namespace esc::python
