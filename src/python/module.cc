// The Python module `hexgait`: the simulator as a batched, deterministic fitness function for
// Python's optimizers, plus traces, stills and movies. It binds the one evaluation seam
// (eval/evaluator.h) and the run layer's option checks (run/), so a genome gives the same bits
// and a mistake the same message as on the command line. InputError becomes ValueError,
// FileError and StorageError (a full disk) OSError, SystemError (no GL context, FFmpeg missing)
// RuntimeError; a wrong dtype is a TypeError.
// Each topic is bound in a file of its own (python/bindings.h); this file makes the module.
#include <pybind11/pybind11.h>

#include <string>

#include "python/bindings.h"
#include "util/error.h"

PYBIND11_MODULE(hexgait, m) {
  using namespace hexgait;
  using namespace hexgait::python;
  m.doc() =
      "hexgait: Nikovski's six-legged mass-spring creature as a fast, deterministic fitness "
      "function (Evaluator), with traces (simulate), stills and movies. Genes are the paper's "
      "4-bit integers in [-8, 7]; offsets are rest-length changes in length units.";
  m.attr("__version__") = HEXGAIT_VERSION;
  // Arrays are numpy's: without it, say which Python this module was built for rather than
  // fail later with numpy's own import error.
  try {
    py::module_::import("numpy");
  } catch (const py::error_already_set&) {
    const std::string running = py::module_::import("sys").attr("executable").cast<std::string>();
    throw py::import_error("hexgait needs numpy, which " + running +
                           " cannot import: run the Python it was built for (" +
                           HEXGAIT_PYTHON_EXECUTABLE +
                           ", whose numpy is Debian's python3-numpy) or a venv made from it "
                           "with --system-site-packages");
  }

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const StorageError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SystemError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  BindArguments(m);
  BindEvaluator(m);
  BindSearch(m);
  BindPictures(m);
  BindReplay(m);
  BindAdapt(m);
  BindNotebook(m);
}
