#include "encode/ffmpeg_api.h"

#include <string>

#include "library_names.h"
#include "util/error.h"
#include "util/shared_library.h"

namespace hexgait {
namespace {

struct Loaded {
  FfmpegApi api;
  std::string error;  // empty when every function was found
};

Loaded Load() {
  Loaded loaded;
  const LibraryName names[] = {HEXGAIT_LIBRARY_AVUTIL, HEXGAIT_LIBRARY_AVCODEC,
                               HEXGAIT_LIBRARY_AVFORMAT};
  const SharedLibrary* libraries[3] = {};
  for (int k = 0; k < 3; ++k) {
    libraries[k] = SharedLibrary::Open(names[k], &loaded.error);
    if (!libraries[k]) {
      loaded.error = "cannot read or write movies: FFmpeg's " + loaded.error;
      return loaded;
    }
  }
  const SharedLibrary& avutil = *libraries[0];
  const SharedLibrary& avcodec = *libraries[1];
  const SharedLibrary& avformat = *libraries[2];
#define HEXGAIT_FFMPEG_BIND(library, function) \
  if (!library.Bind(#function, loaded.api.function, &loaded.error)) return loaded;
  HEXGAIT_FFMPEG_FUNCTIONS(HEXGAIT_FFMPEG_BIND)
#undef HEXGAIT_FFMPEG_BIND
  return loaded;
}

}  // namespace

const FfmpegApi& Ffmpeg() {
  static const Loaded loaded = Load();
  if (!loaded.error.empty()) throw SystemError(loaded.error);
  return loaded.api;
}

std::string AvError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  Ffmpeg().av_strerror(code, text, sizeof text);
  return text;
}

void CodecContextFree::operator()(AVCodecContext* c) const {
  Ffmpeg().avcodec_free_context(&c);
}
void FrameFree::operator()(AVFrame* f) const {
  Ffmpeg().av_frame_free(&f);
}
void PacketFree::operator()(AVPacket* p) const {
  Ffmpeg().av_packet_free(&p);
}

}  // namespace hexgait
