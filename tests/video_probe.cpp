#include "video_probe.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <memory>

namespace cb::test {

namespace {

// Frees libav objects even when a REQUIRE throws half-way.
struct InputCloser {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};
struct CodecFreer {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct PacketFreer {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct FrameFreer {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};

// Y'CbCr -> RGBA as the frame is tagged (BT.709 limited range for our videos), with full
// chroma interpolation so that a thin coloured line is not smeared further by this step.
Image to_rgba(const AVFrame& frame) {
  Image out(frame.width, frame.height);
  SwsContext* sws = sws_getContext(
      frame.width, frame.height, static_cast<AVPixelFormat>(frame.format), frame.width,
      frame.height, AV_PIX_FMT_RGBA, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
      nullptr, nullptr);
  REQUIRE(sws);
  const int* coefficients =
      sws_getCoefficients(frame.colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT);
  sws_setColorspaceDetails(sws, coefficients, frame.color_range == AVCOL_RANGE_JPEG, coefficients,
                           1, 0, 1 << 16, 1 << 16);
  std::uint8_t* dst[1] = {out.rgba.data()};
  const int stride[1] = {frame.width * 4};
  sws_scale(sws, frame.data, frame.linesize, 0, frame.height, dst, stride);
  sws_freeContext(sws);
  return out;
}

}  // namespace

Decoded decode(const std::string& path, int keep) {
  Decoded out;
  AVFormatContext* raw = nullptr;
  REQUIRE(avformat_open_input(&raw, path.c_str(), nullptr, nullptr) == 0);
  const std::unique_ptr<AVFormatContext, InputCloser> fmt(raw);
  REQUIRE(avformat_find_stream_info(fmt.get(), nullptr) >= 0);
  REQUIRE(fmt->nb_streams == 1);
  const AVStream* st = fmt->streams[0];
  out.container = fmt->iformat->name;
  out.codec = avcodec_get_name(st->codecpar->codec_id);
  const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(st->codecpar->format));
  out.pix_fmt = pix ? pix : "";
  out.frame_rate = st->avg_frame_rate;
  out.duration = st->duration != AV_NOPTS_VALUE ? st->duration * av_q2d(st->time_base)
                                                : fmt->duration / double(AV_TIME_BASE);
  const AVCodec* decoder = avcodec_find_decoder(st->codecpar->codec_id);
  REQUIRE(decoder);
  const std::unique_ptr<AVCodecContext, CodecFreer> dec(avcodec_alloc_context3(decoder));
  REQUIRE(avcodec_parameters_to_context(dec.get(), st->codecpar) >= 0);
  REQUIRE(avcodec_open2(dec.get(), decoder, nullptr) == 0);
  const std::unique_ptr<AVPacket, PacketFreer> pkt(av_packet_alloc());
  const std::unique_ptr<AVFrame, FrameFreer> frame(av_frame_alloc());
  auto drain = [&] {
    while (avcodec_receive_frame(dec.get(), frame.get()) == 0) {
      out.width = frame->width, out.height = frame->height;
      out.colorspace = frame->colorspace;
      out.chroma_location = frame->chroma_location;
      if (out.frames++ == keep) out.picture = to_rgba(*frame);
    }
  };
  while (av_read_frame(fmt.get(), pkt.get()) >= 0) {
    REQUIRE(avcodec_send_packet(dec.get(), pkt.get()) >= 0);
    av_packet_unref(pkt.get());
    drain();
  }
  avcodec_send_packet(dec.get(), nullptr);  // flush: frames held for reordering come out
  drain();
  return out;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> top_level_boxes(const std::string& bytes) {
  std::vector<std::string> boxes;
  std::size_t at = 0;
  auto be32 = [&](std::size_t i) {
    return std::uint64_t(std::uint8_t(bytes[i])) << 24 |
           std::uint64_t(std::uint8_t(bytes[i + 1])) << 16 |
           std::uint64_t(std::uint8_t(bytes[i + 2])) << 8 |
           std::uint64_t(std::uint8_t(bytes[i + 3]));
  };
  while (at + 8 <= bytes.size()) {
    std::uint64_t size = be32(at);
    boxes.push_back(bytes.substr(at + 4, 4));
    if (size == 1 && at + 16 <= bytes.size()) size = be32(at + 8) << 32 | be32(at + 12);  // 64-bit
    if (size < 8) break;  // 0: to the end of the file; anything else below 8 is malformed
    at += size;
  }
  return boxes;
}

}  // namespace cb::test
