#include "decoded_video.h"

#include <cstdlib>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libswscale/swscale.h>
}

namespace fooball::testing {

namespace {

struct Contexts {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  ~Contexts() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
  }
};

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(error, text, sizeof text);
  throw std::runtime_error(path + ": " + what + ": " + text);
}

/// The frame as RGB24, turned back with the colour matrix and range its stream names.
std::vector<std::uint8_t> toRgb(Contexts& c, const AVFrame& frame) {
  c.scaler = sws_getCachedContext(c.scaler, frame.width, frame.height, AVPixelFormat(frame.format),
                                  frame.width, frame.height, AV_PIX_FMT_RGB24,
                                  SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                                  nullptr, nullptr);
  const int space = frame.colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
  const int* table = sws_getCoefficients(space);
  sws_setColorspaceDetails(c.scaler, table, frame.color_range == AVCOL_RANGE_JPEG ? 1 : 0, table, 1,
                           0, 1 << 16, 1 << 16);
  std::vector<std::uint8_t> rgb(std::size_t(3 * frame.width * frame.height));
  std::uint8_t* planes[1] = {rgb.data()};
  const int strides[1] = {3 * frame.width};
  sws_scale(c.scaler, frame.data, frame.linesize, 0, frame.height, planes, strides);
  return rgb;
}

}  // namespace

DecodedVideo decodeVideo(const std::string& path, const std::set<int>& keep) {
  Contexts c;
  if (const int error = avformat_open_input(&c.format, path.c_str(), nullptr, nullptr); error < 0)
    fail(path, "could not open", error);
  if (const int error = avformat_find_stream_info(c.format, nullptr); error < 0)
    fail(path, "no stream information", error);
  const int stream = av_find_best_stream(c.format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (stream < 0) fail(path, "no video stream", stream);
  const AVStream& video = *c.format->streams[stream];
  const AVCodec* decoder = avcodec_find_decoder(video.codecpar->codec_id);
  if (!decoder) throw std::runtime_error(path + ": no decoder for its codec");
  c.codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(c.codec, video.codecpar);
  if (const int error = avcodec_open2(c.codec, decoder, nullptr); error < 0)
    fail(path, "could not open the decoder", error);
  c.frame = av_frame_alloc();
  c.packet = av_packet_alloc();

  DecodedVideo result;
  result.decoder = decoder->name;
  result.width = c.codec->width;
  result.height = c.codec->height;
  if (c.format->duration != AV_NOPTS_VALUE)
    result.durationSeconds = double(c.format->duration) / AV_TIME_BASE;
  if (video.avg_frame_rate.den != 0) result.framesPerSecond = av_q2d(video.avg_frame_rate);

  const auto receive = [&] {
    for (;;) {
      const int received = avcodec_receive_frame(c.codec, c.frame);
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      if (received < 0) fail(path, "could not decode", received);
      if (keep.count(result.frameCount)) {
        result.frames.push_back(toRgb(c, *c.frame));
        result.frameIndices.push_back(result.frameCount);
      }
      ++result.frameCount;
      av_frame_unref(c.frame);
    }
  };
  while (av_read_frame(c.format, c.packet) >= 0) {
    if (c.packet->stream_index == stream) {
      if (const int error = avcodec_send_packet(c.codec, c.packet); error < 0)
        fail(path, "could not decode", error);
      receive();
    }
    av_packet_unref(c.packet);
  }
  avcodec_send_packet(c.codec, nullptr);
  receive();
  return result;
}

double meanAbsoluteDifference(const std::vector<std::uint8_t>& a,
                              const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size() || a.empty()) return 255.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += std::abs(int(a[i]) - int(b[i]));
  return sum / double(a.size());
}

}  // namespace fooball::testing
