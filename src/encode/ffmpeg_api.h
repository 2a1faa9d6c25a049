// The FFmpeg functions the encoder and the movie reader call, from libavcodec, libavformat and
// libavutil opened on first use (util/shared_library.h): a command that writes no movie never loads
// FFmpeg or the codec libraries it pulls in. Each function keeps its own name and the type its
// header declares, so a call reads as in FFmpeg's examples: `ff.avcodec_open2(...)`.
#pragma once

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
}

namespace hexgait {

// X(library, function) for every function used; the library is avcodec, avformat or avutil.
#define HEXGAIT_FFMPEG_FUNCTIONS(X)           \
  X(avutil, av_strerror)                      \
  X(avutil, av_log_set_level)                 \
  X(avutil, av_opt_set)                       \
  X(avutil, av_dict_set)                      \
  X(avutil, av_dict_free)                     \
  X(avutil, av_frame_alloc)                   \
  X(avutil, av_frame_free)                    \
  X(avutil, av_frame_get_buffer)              \
  X(avutil, av_frame_make_writable)           \
  X(avcodec, avcodec_find_encoder_by_name)    \
  X(avcodec, avcodec_alloc_context3)          \
  X(avcodec, avcodec_free_context)            \
  X(avcodec, avcodec_open2)                   \
  X(avcodec, avcodec_parameters_from_context) \
  X(avcodec, avcodec_send_frame)              \
  X(avcodec, avcodec_receive_packet)          \
  X(avcodec, av_packet_alloc)                 \
  X(avcodec, av_packet_free)                  \
  X(avcodec, av_packet_rescale_ts)            \
  X(avcodec, av_packet_unref)                 \
  X(avcodec, avcodec_find_decoder)            \
  X(avcodec, avcodec_parameters_to_context)   \
  X(avcodec, avcodec_send_packet)             \
  X(avcodec, avcodec_receive_frame)           \
  X(avformat, avformat_open_input)            \
  X(avformat, avformat_find_stream_info)      \
  X(avformat, av_find_best_stream)            \
  X(avformat, av_read_frame)                  \
  X(avformat, avformat_close_input)           \
  X(avformat, avformat_alloc_output_context2) \
  X(avformat, avformat_new_stream)            \
  X(avformat, avformat_free_context)          \
  X(avformat, avformat_write_header)          \
  X(avformat, av_interleaved_write_frame)     \
  X(avformat, av_write_trailer)               \
  X(avformat, avio_open)                      \
  X(avformat, avio_closep)

struct FfmpegApi {
#define HEXGAIT_FFMPEG_POINTER(library, function) decltype(&::function) function = nullptr;
  HEXGAIT_FFMPEG_FUNCTIONS(HEXGAIT_FFMPEG_POINTER)
#undef HEXGAIT_FFMPEG_POINTER
};

// Owners of FFmpeg's objects, for std::unique_ptr (the encoder's and the movie reader's).
struct CodecContextFree {
  void operator()(AVCodecContext* c) const;
};
struct FrameFree {
  void operator()(AVFrame* f) const;
};
struct PacketFree {
  void operator()(AVPacket* p) const;
};

// FFmpeg's words for an error code (av_strerror), for a message that says why a call failed.
std::string AvError(int code);

// The functions, loaded on the first call. Throws InputError naming the missing library and
// its Debian package when FFmpeg cannot be loaded.
const FfmpegApi& Ffmpeg();

}  // namespace hexgait
