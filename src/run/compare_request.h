// `hexgait compare`, `--expect` and Python's compare: does an image or a movie look like the
// approved one? PNG stills are compared as images, movies frame by frame (same size, same
// number of frames), each by the golden-image rule (image/image_compare.h), the one the
// project's own golden tests use.
#pragma once

#include <string>

#include "image/image_compare.h"
#include "util/progress.h"

namespace hexgait {

struct CompareRequest {
  std::string expected, actual;
  std::string diff;  // a PNG showing where they differ (a movie's worst frame); "" for none
  ImageTolerance tolerance;
};

struct CompareResult {
  bool match = false;
  std::string summary;  // one line: "match: ..." or "differ: ..."
  bool movie = false;
  long long frames = 0;           // compared (1 for an image); both files' when counts differ
  long long expected_frames = 0;  // a movie's
  long long actual_frames = 0;
  long long differing_frames = 0;  // over the tolerance
  long long worst_frame = -1;      // the frame with the most differing pixels (0 for an image)
  ImageDifference worst;           // that frame's difference (its diff image included)
  bool sizes_differ = false;
  std::string diff_path;  // where the diff image was written; "" when none was
};

// Every check before any work, in this order: the tolerance, the two inputs (readable, both a
// .png image or both a movie: .mp4, .mkv, .mov, .webm), the diff path (a .png, not an input,
// its folder writable), then libpng or FFmpeg. Different sizes or frame counts are not an error
// but a mismatch whose summary says so (and no diff image). Throws InputError for bad input,
// SystemError when libpng or FFmpeg cannot load. `on_frames` hears (frames done, 0) per frame of
// a movie.
CompareResult CompareFiles(const CompareRequest& request, const Progress& on_frames = {});

// `out`, just written, against `expected` by the default rule: what `--expect FILE` adds to
// still, filmstrip and render. On a mismatch the diff image goes beside `out`
// (OUT_STEM.diff.png). CheckExpected is the part made before any work (the file exists and is
// of the output's kind).
void CheckExpected(const std::string& expected, const std::string& out);
CompareResult CompareWithExpected(const std::string& expected, const std::string& out);

}  // namespace hexgait
