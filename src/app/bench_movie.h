// `hexgait bench movie`: where a movie's time goes (simulation, render, colour conversion,
// encode), the whole in-process pipeline against piping raw RGBA frames into the ffmpeg
// command-line tool, and the peak memory of short and long movies.
#pragma once

#include <CLI/CLI.hpp>

namespace hexgait {

void AddBenchMovie(CLI::App& bench);

}  // namespace hexgait
