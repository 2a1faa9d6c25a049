#include "run/compare_request.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "encode/ffmpeg_api.h"
#include "encode/video_reader.h"
#include "render/png_io.h"
#include "run/io_paths.h"
#include "run/runtime_needs.h"
#include "util/error.h"
#include "util/output.h"

namespace hexgait {

namespace {

namespace fs = std::filesystem;

std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool IsMovie(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".mp4" || ext == ".mkv" || ext == ".mov" || ext == ".webm";
}

bool IsPng(const std::string& path) {
  return LowerExtension(path) == ".png";
}

// Where `--expect` puts the diff of a mismatch: beside the output, OUT_STEM.diff.png.
std::string ExpectDiffPath(const std::string& out) {
  return (fs::path(out).parent_path() / fs::path(out).stem()).string() + ".diff.png";
}

// A file to compare: a regular file this process can open.
void CheckReadable(const std::string& path, const std::string& what) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    throw InputError(what + " '" + path + "' is not a file");
  }
  if (!std::ifstream(path, std::ios::binary)) {
    throw InputError(what + " '" + path + "' cannot be read");
  }
}

// "1234 of 76800 pixels (1.61%)"
std::string PixelsText(const ImageDifference& d) {
  char text[96];
  std::snprintf(text, sizeof text, "%lld of %lld pixels (%.4g%%)", d.different_pixels, d.pixels,
                100 * d.fraction());
  return text;
}

std::string RuleText(const ImageTolerance& t) {
  char text[96];
  std::snprintf(text, sizeof text, "by more than %d levels (tolerance %.4g%% of the pixels)",
                t.pixel_threshold, 100 * t.max_different_fraction);
  return text;
}

std::string SizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

void WriteDiff(const std::string& path, CompareResult& result) {
  if (path.empty() || result.sizes_differ || result.worst_frame < 0) return;
  WritePng(path, result.worst.diff);
  result.diff_path = path;
}

CompareResult CompareImageFiles(const CompareRequest& request) {
  CompareResult result;
  const Image expected = ReadPng(request.expected);
  const Image actual = ReadPng(request.actual);
  result.frames = result.expected_frames = result.actual_frames = 1;
  if (expected.width != actual.width || expected.height != actual.height) {
    result.sizes_differ = true;
    result.summary = "differ: sizes differ: expected " + SizeText(expected.width, expected.height) +
                     ", actual " + SizeText(actual.width, actual.height);
    return result;
  }
  result.worst = CompareImages(expected, actual, request.tolerance);
  result.worst_frame = 0;
  result.match = result.worst.within;
  result.differing_frames = result.match ? 0 : 1;
  result.summary = std::string(result.match ? "match: " : "differ: ") + PixelsText(result.worst) +
                   " differ " + RuleText(request.tolerance) + "; largest change " +
                   std::to_string(result.worst.max_difference);
  return result;
}

CompareResult CompareMovieFiles(const CompareRequest& request, const Progress& on_frames) {
  CompareResult result;
  result.movie = true;
  VideoReader expected(request.expected), actual(request.actual);
  if (expected.width() != actual.width() || expected.height() != actual.height()) {
    result.sizes_differ = true;
    result.summary = "differ: frame sizes differ: expected " +
                     SizeText(expected.width(), expected.height()) + ", actual " +
                     SizeText(actual.width(), actual.height());
    return result;
  }
  Image a, b;
  bool more_expected = expected.Next(&a), more_actual = actual.Next(&b);
  while (more_expected && more_actual) {
    ImageDifference d = CompareImages(a, b, request.tolerance);
    if (!d.within) ++result.differing_frames;
    if (result.worst_frame < 0 || d.different_pixels > result.worst.different_pixels ||
        (d.different_pixels == result.worst.different_pixels &&
         d.max_difference > result.worst.max_difference)) {
      result.worst = std::move(d);
      result.worst_frame = result.frames;
    }
    ++result.frames;
    if (on_frames) on_frames("frames", result.frames, 0);
    more_expected = expected.Next(&a);
    more_actual = actual.Next(&b);
  }
  result.expected_frames = result.actual_frames = result.frames;
  while (more_expected) ++result.expected_frames, more_expected = expected.Next(&a);
  while (more_actual) ++result.actual_frames, more_actual = actual.Next(&b);
  if (result.expected_frames != result.actual_frames) {
    result.summary = "differ: frame counts differ: expected " +
                     std::to_string(result.expected_frames) + ", actual " +
                     std::to_string(result.actual_frames);
    return result;
  }
  result.match = result.differing_frames == 0 && result.frames > 0;
  const std::string worst = result.worst_frame < 0
                                ? "no frames"
                                : "worst frame " + std::to_string(result.worst_frame) + ": " +
                                      PixelsText(result.worst) + " differ " +
                                      RuleText(request.tolerance) + ", largest change " +
                                      std::to_string(result.worst.max_difference);
  result.summary = std::string(result.match ? "match: " : "differ: ") +
                   std::to_string(result.differing_frames) + " of " +
                   std::to_string(result.frames) + " frames over the tolerance; " + worst;
  return result;
}

}  // namespace

CompareResult CompareFiles(const CompareRequest& request, const Progress& on_frames) {
  CheckImageTolerance(request.tolerance);
  CheckReadable(request.expected, "expected");
  CheckReadable(request.actual, "actual");
  const bool movie = IsMovie(request.expected);
  if (!movie && !IsPng(request.expected)) {
    throw InputError("expected '" + request.expected +
                     "': not a .png image or a .mp4, .mkv, .mov or .webm movie");
  }
  if (IsMovie(request.actual) != movie || (!movie && !IsPng(request.actual))) {
    throw InputError("actual '" + request.actual + "' is not " +
                     (movie ? "a movie" : "a .png image") + " like expected '" + request.expected +
                     "'");
  }
  if (!request.diff.empty()) {
    IoPaths()
        .Input("EXPECTED", request.expected)
        .Input("ACTUAL", request.actual)
        .Output("--diff", request.diff)
        .Check();
    CheckExtension(request.diff, ".png", "--diff");
    CheckOutputPath(request.diff, "--diff");
  }
  RuntimeNeeds needs;
  needs.png = !movie || !request.diff.empty();
  CheckRuntime(needs);
  if (movie) Ffmpeg();  // throws SystemError when FFmpeg cannot load
  CompareResult result = movie ? CompareMovieFiles(request, on_frames) : CompareImageFiles(request);
  WriteDiff(request.diff, result);
  return result;
}

void CheckExpected(const std::string& expected, const std::string& out) {
  if (expected.empty()) return;
  CheckReadable(expected, "--expect");
  if (IsMovie(expected) != IsMovie(out) || IsPng(expected) != IsPng(out)) {
    throw InputError("--expect '" + expected + "' is not the same kind of file as --out '" + out +
                     "'");
  }
  IoPaths().Input("--expect", expected).Output("--out", out).Check();
  IoPaths().Input("--expect", expected).Output("--expect's diff", ExpectDiffPath(out)).Check();
  CheckOutputPath(ExpectDiffPath(out), "--expect's diff image");
}

CompareResult CompareWithExpected(const std::string& expected, const std::string& out) {
  CompareRequest request;
  request.expected = expected;
  request.actual = out;
  CompareResult result = CompareFiles(request);
  if (!result.match) WriteDiff(ExpectDiffPath(out), result);
  return result;
}

}  // namespace hexgait
