// The options shared by `render` (one movie), `movie` (the report's set) and `repertoire
// --movie`: frame size, rate, playback speed and what is drawn (run/movie_request.h checks them
// and makes the movie), and the line a command prints of a finished movie.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "app/view_options.h"
#include "run/movie_request.h"

namespace hexgait {

// `with_frames` adds --frames (one movie per command only).
void AddMovieOptions(CLI::App* command, MovieRequest& options, bool with_frames);

// One line: the file, its frames, where the time went and the peak memory.
void PrintMovieSummary(const std::string& path, const MovieStats& stats,
                       const MovieSettings& settings);

}  // namespace hexgait
