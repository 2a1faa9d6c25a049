// Ctrl-C inside a long call from Python: hexgait's loops run with the GIL released, where
// Python's own signal handler cannot run, so every long binding runs its work through
// Interruptible and polls CheckPythonSignals between pieces of it.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string_view>

#include "util/error.h"
#include "util/stop_signal.h"

namespace hexgait::python {

namespace py = pybind11;

// From a call that released the GIL: raises KeyboardInterrupt (or what a Python signal handler
// raises) if a signal arrived. A few microseconds; called every few milliseconds of work.
inline void CheckPythonSignals() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// The progress hook of every long call from Python (util/progress.h): it only listens for
// signals.
inline void CheckPythonSignalsBetween(std::string_view, long long, long long) {
  CheckPythonSignals();
}

inline bool OnMainThread() {
  // An integer, not a Python object: a static object would be released after the interpreter.
  static const unsigned long main_thread =
      py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  return PyThread_get_thread_ident() == main_thread;
}

// Runs `work` (with the GIL released unless `keep_gil`) so that a Ctrl-C is heard at once: on
// the main thread, where Python handles signals, SIGINT both trips Python's handler and asks
// hexgait's loops to stop (ForwardedStop; the evaluator polls every 40 steps, inside a batch of
// lanes), and the Stopped that ends the work becomes what Python's handler raises
// (KeyboardInterrupt). Elsewhere the work runs to its end, as Python code there would.
template <class Work>
auto Interruptible(Work&& work, bool keep_gil = false) -> decltype(work()) {
  std::optional<ForwardedStop> forward;
  if (OnMainThread()) forward.emplace();
  try {
    if (keep_gil) return work();
    py::gil_scoped_release release;
    return work();
  } catch (const Stopped&) {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    PyErr_SetNone(PyExc_KeyboardInterrupt);  // the handler did not raise: the work is gone
    throw py::error_already_set();
  }
}

}  // namespace hexgait::python
