#include "video_encoder.h"

#include <cerrno>
#include <optional>

#include "gif_palette.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

namespace fooball::video {

/// Owned FFmpeg objects, freed in the reverse order of making.
struct VideoEncoder::Ffmpeg {
  AVFormatContext* format = nullptr;
  AVStream* stream = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;       ///< RGB → YUV 4:2:0 (MP4, WebM)
  std::optional<GifPalette> palette;  ///< RGB → 256 colours (GIF), from the first frame

  ~Ffmpeg() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  }
};

namespace {

std::string errorText(int error) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(error, text, sizeof text);
  std::string message = text;
  if (error == AVERROR(ENOSPC)) message += " (the disk is full)";
  return message;
}

/// The encoder of `format` that this FFmpeg has, best first: Debian's libavcodec59 has libx264,
/// libvpx-vp9, libvpx and gif; other builds may lack the first two.
const AVCodec* findEncoder(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4:
      return avcodec_find_encoder_by_name("libx264");
    case VideoFormat::WebM:
      if (const AVCodec* vp9 = avcodec_find_encoder_by_name("libvpx-vp9")) return vp9;
      return avcodec_find_encoder_by_name("libvpx");
    case VideoFormat::Gif:
      return avcodec_find_encoder_by_name("gif");
  }
  return nullptr;
}

/// Quality and speed, per encoder. Screen pictures are flat colours with sharp edges: a
/// constant quality (CRF) spends bits where the picture moves and next to none on the still
/// black, and the speeds chosen keep a 1280×720 recording near real time on two cores.
void setEncoderOptions(const AVCodec& codec, AVCodecContext& context, AVDictionary** options) {
  const std::string name = codec.name;
  if (name == "libx264") {
    av_dict_set(options, "preset", "faster", 0);
    av_dict_set(options, "tune", "animation", 0);  // flat areas, sharp edges
    av_dict_set(options, "crf", "20", 0);
  } else if (name == "libvpx-vp9") {
    context.bit_rate = 0;  // constant quality alone
    av_dict_set(options, "crf", "32", 0);
    av_dict_set(options, "deadline", "good", 0);
    av_dict_set(options, "cpu-used", "5", 0);
    av_dict_set(options, "row-mt", "1", 0);
  } else if (name == "libvpx") {
    context.bit_rate = 4'000'000;  // VP8's CRF is a floor under this ceiling
    av_dict_set(options, "crf", "10", 0);
    av_dict_set(options, "deadline", "good", 0);
    av_dict_set(options, "cpu-used", "4", 0);
  }
}

}  // namespace

VideoEncoder::VideoEncoder(const std::string& path, const VideoSettings& settings)
    : path_(path), settings_(settings), ffmpeg_(std::make_unique<Ffmpeg>()) {
  // FFmpeg's own log to stderr: its errors only. The encoders' statistics and banners would
  // print at every recording; what goes wrong reaches the caller as a VideoError.
  av_log_set_level(AV_LOG_ERROR);
  if (const std::string problem = checkVideoSettings(settings); !problem.empty())
    throw VideoError(path + ": " + problem);
  const AVCodec* codec = findEncoder(settings.format);
  if (!codec) {
    throw VideoError(path + ": this FFmpeg has no " + std::string(formatTitle(settings.format)) +
                     " encoder; record to another type (.mp4, .webm or .gif)");
  }
  Ffmpeg& f = *ffmpeg_;
  const std::string muxer(extensionOf(settings.format));
  if (const int error =
          avformat_alloc_output_context2(&f.format, nullptr, muxer.c_str(), path.c_str());
      error < 0) {
    fail("could not prepare the " + muxer + " file", error);
  }
  f.stream = avformat_new_stream(f.format, nullptr);
  f.codec = avcodec_alloc_context3(codec);
  f.frame = av_frame_alloc();
  f.packet = av_packet_alloc();
  if (!f.stream || !f.codec || !f.frame || !f.packet) fail("out of memory", AVERROR(ENOMEM));

  AVCodecContext& context = *f.codec;
  context.width = settings.width;
  context.height = settings.height;
  context.time_base = {1, settings.framesPerSecond};
  context.framerate = {settings.framesPerSecond, 1};
  context.gop_size = 2 * settings.framesPerSecond;  // a key frame every 2 s: seeking stays quick
  const bool gif = settings.format == VideoFormat::Gif;
  context.pix_fmt = gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
  if (!gif) {
    // The colours as the scaler makes them (BT.709, studio range), said in the stream so that
    // players turn them back into the same RGB.
    context.colorspace = AVCOL_SPC_BT709;
    context.color_primaries = AVCOL_PRI_BT709;
    context.color_trc = AVCOL_TRC_BT709;
    context.color_range = AVCOL_RANGE_MPEG;
  }
  if (f.format->oformat->flags & AVFMT_GLOBALHEADER) context.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  setEncoderOptions(*codec, context, &options);
  const int opened = avcodec_open2(&context, codec, &options);
  av_dict_free(&options);
  if (opened < 0) fail(std::string("could not start the ") + codec->name + " encoder", opened);
  f.stream->time_base = context.time_base;
  f.stream->avg_frame_rate = context.framerate;
  if (const int error = avcodec_parameters_from_context(f.stream->codecpar, &context); error < 0)
    fail("could not prepare the stream", error);

  f.frame->format = context.pix_fmt;
  f.frame->width = context.width;
  f.frame->height = context.height;
  if (const int error = av_frame_get_buffer(f.frame, 0); error < 0) fail("out of memory", error);
  if (!gif) {
    // Each chroma sample the mean of the pixels it covers (SWS_FULL_CHR_H_INP), not the colour of
    // one of them: a ball a few pixels wide keeps its colour.
    f.scaler = sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGB24, settings.width,
                              settings.height, AV_PIX_FMT_YUV420P,
                              SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr,
                              nullptr, nullptr);
    if (!f.scaler) fail("could not prepare the colour conversion", AVERROR(EINVAL));
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(f.scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  if (const int error = avio_open(&f.format->pb, path.c_str(), AVIO_FLAG_WRITE); error < 0)
    fail("could not create the file", error);
  if (const int error = avformat_write_header(f.format, nullptr); error < 0)
    fail("could not write", error);
}

VideoEncoder::~VideoEncoder() {
  try {
    finish();
  } catch (const VideoError&) {
    // Reported by nobody: the caller is gone or already failing. The file holds what it holds.
  }
}

std::string VideoEncoder::codecName() const {
  return ffmpeg_->codec && ffmpeg_->codec->codec ? ffmpeg_->codec->codec->name : "";
}

std::int64_t VideoEncoder::bytesWritten() const {
  if (finished_) return finalBytes_;
  const AVFormatContext* format = ffmpeg_->format;
  return format && format->pb ? avio_tell(format->pb) : 0;
}

void VideoEncoder::fail(const std::string& what, int error) const {
  throw VideoError(path_ + ": " + what + ": " + errorText(error));
}

void VideoEncoder::addFrame(const RgbFrame& frame) {
  if (finished_) throw VideoError(path_ + ": the recording is finished");
  if (frame.width != settings_.width || frame.height != settings_.height) {
    throw VideoError(path_ + ": a frame of " + std::to_string(frame.width) + "x" +
                     std::to_string(frame.height) + " px in a video of " +
                     std::to_string(settings_.width) + "x" + std::to_string(settings_.height));
  }
  Ffmpeg& f = *ffmpeg_;
  if (const int error = av_frame_make_writable(f.frame); error < 0) fail("out of memory", error);
  if (settings_.format == VideoFormat::Gif) {
    if (!f.palette) f.palette.emplace(frame);
    f.palette->map(frame, f.frame->data[0], f.frame->linesize[0]);
    const auto& colours = f.palette->colours();
    std::copy(colours.begin(), colours.end(), reinterpret_cast<std::uint32_t*>(f.frame->data[1]));
  } else {
    const std::uint8_t* source[1] = {frame.pixels};
    const int sourceStride[1] = {static_cast<int>(frame.bytesPerLine)};
    sws_scale(f.scaler, source, sourceStride, 0, frame.height, f.frame->data, f.frame->linesize);
  }
  f.frame->pts = framesAdded_;
  encode(false);
  ++framesAdded_;
}

void VideoEncoder::encode(bool flush) {
  Ffmpeg& f = *ffmpeg_;
  if (const int error = avcodec_send_frame(f.codec, flush ? nullptr : f.frame);
      error < 0 && error != AVERROR_EOF) {
    fail("could not encode a frame", error);
  }
  for (;;) {
    const int received = avcodec_receive_packet(f.codec, f.packet);
    if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
    if (received < 0) fail("could not encode a frame", received);
    // Every frame lasts one frame time: the container's duration ends at the last frame's end.
    if (f.packet->duration == 0) f.packet->duration = 1;
    av_packet_rescale_ts(f.packet, f.codec->time_base, f.stream->time_base);
    f.packet->stream_index = f.stream->index;
    if (const int error = av_interleaved_write_frame(f.format, f.packet); error < 0)
      fail("could not write", error);
  }
}

void VideoEncoder::finish() {
  if (finished_) return;
  finished_ = true;  // whatever follows fails, it is not tried twice
  Ffmpeg& f = *ffmpeg_;
  if (!f.format || !f.format->pb) return;  // never opened: nothing to finish
  std::optional<VideoError> firstError;
  const auto attempt = [&](auto&& step) {
    try {
      step();
    } catch (const VideoError& error) {
      if (!firstError) firstError = error;
    }
  };
  // Each step even when one before it failed: a trailer after a failed drain still indexes
  // the frames written, and the file is closed in any case.
  attempt([&] { encode(true); });
  attempt([&] {
    if (const int error = av_write_trailer(f.format); error < 0) fail("could not finish", error);
  });
  attempt([&] {
    avio_flush(f.format->pb);
    finalBytes_ = avio_tell(f.format->pb);
    const int error = f.format->pb->error;
    avio_closep(&f.format->pb);
    if (error < 0) fail("could not write", error);
  });
  if (firstError) throw *firstError;
}

}  // namespace fooball::video
