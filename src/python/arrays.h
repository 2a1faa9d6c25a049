// NumPy in and out of the Python module: checked conversions of the arrays users pass (genomes,
// offsets) and the dict of arrays evaluate() returns. A wrong dtype raises TypeError, a wrong
// shape or value ValueError, with messages naming the argument and the offending element.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sim/step_loop.h"

namespace hexgait::python {

namespace py = pybind11;

// `array` as an (n, genes) table of genes in [-8, 7]: any integer dtype; a 1-D array of
// `genes` values is one genome. Row-major, n * genes values.
std::vector<int8_t> GenesFromArray(const py::handle& array, int genes, const char* name, int* rows);

// `array` as an (n, genes) table of finite rest-length offsets: any real or integer dtype.
std::vector<double> OffsetsFromArray(const py::handle& array, int genes, const char* name,
                                     int* rows);

// A run's result as Python sees it, field by field: `visit(name, get)` where get(result) is the
// field's value. Both result dicts (evaluate's arrays, simulate's scalars) are built from it.
template <class Visit>
void ForEachResultField(Visit&& visit) {
  visit("distance", [](const RunResult& r) { return r.distance; });
  visit("fell", [](const RunResult& r) { return r.fell; });
  visit("fall_time", [](const RunResult& r) { return r.fell ? r.fall_time : std::nan(""); });
  visit("fall_cycle", [](const RunResult& r) { return r.fall_cycle; });
  visit("diverged", [](const RunResult& r) { return r.diverged; });
  visit("steps", [](const RunResult& r) { return r.steps; });
  visit("end_time", [](const RunResult& r) { return r.end_time; });
  visit("min_body_height", [](const RunResult& r) { return r.min_body_height; });
  visit("max_tilt_degrees", [](const RunResult& r) { return r.max_tilt_degrees; });
  visit("mean_feet_on_ground", [](const RunResult& r) { return r.mean_feet_on_ground; });
}

// The results as a dict of NumPy arrays, one element per creature: distance, fell, fall_time
// (NaN if it did not fall), fall_cycle (0 if it did not fall), diverged, steps, end_time,
// min_body_height, max_tilt_degrees, mean_feet_on_ground; and duty_factors, an (n, legs) array
// of each leg's fraction of checks on the ground before the fall.
py::dict ResultsToDict(std::span<const RunResult> results, int legs);
// One result as a dict of Python scalars, the same fields; fall_time and fall_cycle are None if
// it did not fall.
py::dict ResultToDict(const RunResult& result, int legs);

}  // namespace hexgait::python
