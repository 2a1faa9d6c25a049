// --view, --camera, --track (and --cues where frames follow each other): one place for the
// camera and gait-cue options `still`, `render`, `movie`, `filmstrip` and `figures` share.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "run/view_request.h"

namespace hexgait {

// `with_cues` adds --cues; `default_view` names the preset --help shows.
void AddViewOptions(CLI::App* command, ViewRequest& options, bool with_cues,
                    const std::string& default_view = "three-quarter");

// --gl: the OpenGL backend of a command that draws (set as the option is parsed).
void AddGlOption(CLI::App* command);

}  // namespace hexgait
