// What Jupyter shows inline: replay_html's page and render_movie's movie are strings (the page's
// HTML, the movie's path) of classes that also have _repr_html_, so a notebook cell ending in
// either displays the replay (in a sandboxed iframe) or plays the movie, while every other use
// of the string is unchanged.
#include <pybind11/eval.h>
#include <pybind11/pybind11.h>

#include <string>

#include "python/bindings.h"

namespace hexgait::python {

namespace {

// Movies above this are linked rather than embedded: a notebook carries what it shows.
constexpr long long kMaxEmbeddedMovieBytes = 64ll << 20;

constexpr const char* kClasses = R"PY(
import base64 as _base64
import html as _html
import os as _os


class ReplayPage(str):
    """The replay page's HTML (a str); Jupyter shows the page itself."""

    def _repr_html_(self):
        return ('<iframe sandbox="allow-scripts" style="width:100%;height:560px;border:0" '
                'srcdoc="' + _html.escape(self, quote=True) + '"></iframe>')


class Movie(str):
    """The path of a movie hexgait wrote (a str); Jupyter plays it."""

    def _repr_html_(self):
        if _os.path.getsize(self) > MAX_EMBEDDED_MOVIE_BYTES:
            return '<a href="' + _html.escape(self, quote=True) + '">' + _html.escape(self) + '</a>'
        with open(self, "rb") as f:
            data = _base64.b64encode(f.read()).decode("ascii")
        return ('<video controls loop style="max-width:100%" src="data:video/mp4;base64,' + data +
                '"></video>')
)PY";

}  // namespace

void BindNotebook(py::module_& m) {
  py::dict scope;
  scope["__builtins__"] = py::module_::import("builtins");
  scope["__name__"] = "hexgait";
  scope["MAX_EMBEDDED_MOVIE_BYTES"] = kMaxEmbeddedMovieBytes;
  py::exec(kClasses, scope);
  m.attr("ReplayPage") = scope["ReplayPage"];
  m.attr("Movie") = scope["Movie"];
}

py::object AsReplayPage(const std::string& html) {
  return py::module_::import("hexgait").attr("ReplayPage")(html);
}

py::object AsMovie(const std::string& path) {
  return py::module_::import("hexgait").attr("Movie")(path);
}

}  // namespace hexgait::python
