// The module's topics, each bound by one function in a file of its own; module.cc calls them.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace hexgait::python {

namespace py = pybind11;

void BindArguments(py::module_& m);  // arguments.cc: Creature, MotorProgram, inspect
void BindEvaluator(py::module_& m);  // evaluator.cc: Evaluator, simulate, genome files
void BindSearch(py::module_& m);     // search.cc: Search
void BindPictures(py::module_& m);   // pictures.cc: render_still, render_movie
void BindReplay(py::module_& m);     // replay.cc: replay_html
void BindAdapt(py::module_& m);      // adapt.cc: adapt, GaussianProcess
void BindNotebook(py::module_& m);   // notebook.cc: ReplayPage, Movie (shown inline in Jupyter)

// replay_html's and render_movie's results: strings that Jupyter displays (notebook.cc).
py::object AsReplayPage(const std::string& html);
py::object AsMovie(const std::string& path);

}  // namespace hexgait::python
