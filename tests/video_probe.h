// Reading a video back for tests: what a player would see (container, codec, pixel format,
// size, frame count, frame rate, duration, colour tags) and one frame as RGBA, decoded with
// libavformat/libavcodec and converted with libswscale as the stream's tags say. Shared by
// test_video.cpp (the encoder) and test_render_cli.cpp (the `render` command).
#pragma once

extern "C" {
#include <libavutil/pixfmt.h>
#include <libavutil/rational.h>
}

#include <string>
#include <vector>

#include "output/image.h"

namespace cb::test {

struct Decoded {
  std::string container, codec, pix_fmt;  // libav's names: "mov,mp4,...", "h264", "yuv420p"
  int width = 0, height = 0, frames = 0;
  AVRational frame_rate{0, 1};  // the stream's average frame rate
  double duration = 0;          // seconds, from the stream (else the container)
  AVColorSpace colorspace = AVCOL_SPC_UNSPECIFIED;
  AVChromaLocation chroma_location = AVCHROMA_LOC_UNSPECIFIED;  // as the stream tags it
  Image picture;  // frame `keep` (in presentation order) as RGBA; empty if there is none
};

// Decodes every frame of the file's only stream (Catch REQUIREs on any libav failure).
// `keep` < 0 keeps no picture.
Decoded decode(const std::string& path, int keep);

// The whole file as bytes.
std::string read_bytes(const std::string& path);

// The types of an MP4's top-level boxes in file order ("ftyp", "moov", "mdat", ...).
std::vector<std::string> top_level_boxes(const std::string& bytes);

}  // namespace cb::test
