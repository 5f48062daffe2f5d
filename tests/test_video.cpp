// The video encoder: what it writes is decoded again (video_probe.h, libavformat/libavcodec) and
// checked for container, codec, size, frame count, timing, layout, reproducibility and
// picture fidelity; failures must leave no file under the requested name.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "output/gif_palette.h"
#include "output/output_file.h"
#include "output/video_encoder.h"
#include "output/yuv420.h"
#include "test_support.h"
#include "video_probe.h"

namespace fs = std::filesystem;
using cb::Image;
using cb::test::decode;
using cb::test::Decoded;
using cb::test::read_bytes;
using cb::test::top_level_boxes;

namespace {

struct TempDir : cb::test::TempDir {
  TempDir() : cb::test::TempDir("chainbreak-video") {}
};

void fill(Image& im, int x0, int y0, int w, int h, int r, int g, int b) {
  for (int y = std::max(0, y0); y < std::min(im.height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(im.width, x0 + w); ++x) {
      std::uint8_t* p = im.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(r), p[1] = static_cast<std::uint8_t>(g);
      p[2] = static_cast<std::uint8_t>(b), p[3] = 255;
    }
}

// Frame k: a dark background, a static green square, an orange rectangle moving 5 px per
// frame, and coloured stripes along the right and bottom edges (so padding is visible).
Image make_frame(int w, int h, int k) {
  Image im(w, h);
  fill(im, 0, 0, w, h, 40, 60, 90);
  fill(im, w - 8, 0, 8, h, 200, 200, 40);
  fill(im, 0, h - 8, w, 8, 150, 40, 150);
  fill(im, w - 80, 20, 40, 40, 60, 180, 75);
  fill(im, 10 + 5 * k, h / 2 - 20 + k % 5, 60, 40, 230, 120, 30);
  return im;
}

// How frames reach the encoder: RGBA (converted by swscale inside the encoder), or already
// Y'CbCr 4:2:0 from output/yuv420.h, as `render` hands them over.
enum class Input { rgba, planar };

void encode(const std::string& path, int w, int h, int frames,
            cb::VideoSettings settings = cb::VideoSettings{}, Input input = Input::rgba) {
  settings.width = w, settings.height = h, settings.fps = 30;
  auto sink = cb::open_video(path, settings);
  for (int k = 0; k < frames; ++k) {
    const Image frame = make_frame(w, h, k);
    if (input == Input::rgba) {
      sink->push(frame);
      continue;
    }
    const auto size = sink->yuv420_size();
    REQUIRE(size);
    cb::Yuv420Image picture = sink->spare_yuv420();
    cb::rgba_to_yuv420({frame.rgba.data(), w, h, w * 4, false}, size->width, size->height, picture);
    sink->push_yuv420(std::move(picture));
  }
  sink->finish();
}

// Per-channel mean and max absolute difference over "flat" pixels: those whose 7x7
// neighbourhood in the input has one colour (edges blur under 4:2:0 chroma and DCT).
struct Fidelity {
  double mean[3] = {0, 0, 0};
  int max = 0;
};
Fidelity compare_flat(const Image& input, const Image& decoded) {
  Fidelity f;
  long n = 0;
  for (int y = 3; y < input.height - 3; ++y)
    for (int x = 3; x < input.width - 3; ++x) {
      bool flat = true;
      for (int dy = -3; dy <= 3 && flat; ++dy)
        for (int dx = -3; dx <= 3 && flat; ++dx)
          flat = std::equal(input.pixel(x, y), input.pixel(x, y) + 3, input.pixel(x + dx, y + dy));
      if (!flat) continue;
      ++n;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(input.pixel(x, y)[c] - decoded.pixel(x, y)[c]);
        f.mean[c] += d;
        f.max = std::max(f.max, d);
      }
    }
  for (double& m : f.mean) m /= static_cast<double>(n);
  return f;
}

// Where a decoded picture shows make_frame's orange rectangle: the first column along row
// h / 2 (inside the rectangle for every k), then the first row along the column 30 px right
// of that, whose red channel is past half-way from the background (40) to the orange (230).
// Nothing else left of or above the rectangle on those lines is that red.
struct Edges {
  int left = -1, top = -1;
};
Edges orange_edges(const Image& im, int h) {
  Edges e;
  for (int x = 0; x < im.width && e.left < 0; ++x)
    if (im.pixel(x, h / 2)[0] > 135) e.left = x;
  if (e.left < 0 || e.left + 30 >= im.width) return e;
  for (int y = 0; y < im.height && e.top < 0; ++y)
    if (im.pixel(e.left + 30, y)[0] > 135) e.top = y;
  return e;
}

// Frames decoded from several places in the clip, each against its own input: the rectangle
// where make_frame draws it in that frame (left edge 10 + 5k, top edge h / 2 - 20 + k % 5)
// within `edge` px (measured: exactly there for H.264, VP9 and GIF), and the flat colours
// within 1 level on average (measured <= 0.14 for H.264, 0.25 for VP9, 0 for GIF). Frames are
// 5 px apart: a frame 3 off (decoding 18 for 15) puts the edges 15 px away and the mean
// error at 2.5 .. 2.7, which the tests' single-frame bounds (3 and 4) let pass.
void check_frames(const std::string& path, int w, int h, int edge) {
  for (int k : {0, 1, 7, 15, 18, 29}) {
    const Decoded d = decode(path, k);
    INFO("frame " << k);
    REQUIRE(d.picture.width >= w);
    REQUIRE(d.picture.height >= h);
    const Edges e = orange_edges(d.picture, h);
    CHECK(std::abs(e.left - (10 + 5 * k)) <= edge);
    CHECK(std::abs(e.top - (h / 2 - 20 + k % 5)) <= edge);
    const Fidelity f = compare_flat(make_frame(w, h, k), d.picture);
    for (double m : f.mean) CHECK(m < 1.0);
  }
}

}  // namespace

TEST_CASE("MP4: H.264 yuv420p, exact timing, moov first, reproducible, faithful", "[video]") {
  TempDir dir;
  const std::string a = dir.file("a.mp4"), b = dir.file("b.mp4");
  encode(a, 320, 240, 30);
  encode(b, 320, 240, 30);
  CHECK(dir.names() == std::vector<std::string>{"a.mp4", "b.mp4"});  // no temporary left

  const Decoded d = decode(a, 15);
  CHECK(d.container.find("mp4") != std::string::npos);
  CHECK(d.codec == "h264");
  CHECK(d.pix_fmt == "yuv420p");
  CHECK(d.width == 320);
  CHECK(d.height == 240);
  CHECK(d.frames == 30);
  CHECK(d.frame_rate.num == 30);
  CHECK(d.frame_rate.den == 1);
  CHECK(d.duration == Approx(1.0).margin(1e-9));  // 30 frames / 30 fps, exact time base
  CHECK(d.colorspace == AVCOL_SPC_BT709);

  // faststart: the index (moov) precedes the media data (mdat), so playback starts at once.
  const std::string bytes = read_bytes(a);
  const auto boxes = top_level_boxes(bytes);
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  REQUIRE(moov != boxes.end());
  REQUIRE(mdat != boxes.end());
  CHECK(moov < mdat);
  CHECK(bytes.find("Lavf") == std::string::npos);  // bit-exact muxing: no library version tag

  CHECK(bytes == read_bytes(b));  // same frames, same settings: the same bytes

  // crf 18 on flat colours: small errors, from 4:2:0 and 8-bit Y'CbCr rounding. Measured
  // mean <= 0.11 and max 8 levels; the bounds leave room for other x264 builds.
  const Fidelity f = compare_flat(make_frame(320, 240, 15), d.picture);
  for (double m : f.mean) CHECK(m < 3.0);
  CHECK(f.max < 40);
  check_frames(a, 320, 240, 1);
}

TEST_CASE("MP4: odd sizes are padded by one pixel with the edge colour", "[video]") {
  const Input how = GENERATE(Input::rgba, Input::planar);
  INFO((how == Input::rgba ? "RGBA input" : "Y'CbCr input"));
  TempDir dir;
  const std::string path = dir.file("odd.mp4");
  encode(path, 321, 241, 30, {}, how);
  const Decoded d = decode(path, 0);
  CHECK(d.width == 322);   // 321 + 1 column
  CHECK(d.height == 242);  // 241 + 1 row
  CHECK(d.frames == 30);
  REQUIRE(d.picture.width == 322);
  const Image input = make_frame(321, 241, 0);
  const Fidelity f = compare_flat(input, d.picture);
  for (double m : f.mean) CHECK(m < 3.0);
  // The added column repeats column 320 (the yellow stripe), the added row repeats row 240
  // (the purple stripe): within 8 levels, the codec's error on a flat stripe.
  for (int y = 20; y < 200; y += 10)
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(d.picture.pixel(321, y)[c] - input.pixel(320, y)[c]) < 8);
  for (int x = 20; x < 200; x += 10)
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(d.picture.pixel(x, 241)[c] - input.pixel(x, 240)[c]) < 8);
  check_frames(path, 321, 241, 1);
}

TEST_CASE("WebM: VP9 keeps odd sizes and every frame", "[video]") {
  const Input how = GENERATE(Input::rgba, Input::planar);
  INFO((how == Input::rgba ? "RGBA input" : "Y'CbCr input"));
  TempDir dir;
  const std::string path = dir.file("clip.webm");
  encode(path, 321, 241, 30, {}, how);
  const Decoded d = decode(path, 15);
  CHECK(d.container.find("webm") != std::string::npos);
  CHECK(d.codec == "vp9");
  CHECK(d.width == 321);
  CHECK(d.height == 241);
  CHECK(d.frames == 30);
  CHECK(d.frame_rate.num == 30);
  CHECK(d.frame_rate.den == 1);
  CHECK(d.duration == Approx(1.0).margin(1e-3));  // WebM counts time in whole milliseconds
  // VP9 at crf 32 and real-time speed: looser than H.264 at crf 18 (measured mean <= 0.2).
  const Fidelity f = compare_flat(make_frame(321, 241, 15), d.picture);
  for (double m : f.mean) CHECK(m < 4.0);
  check_frames(path, 321, 241, 1);
}

TEST_CASE("GIF: every frame, the size, close colours, loops forever", "[video]") {
  TempDir dir;
  const std::string path = dir.file("clip.gif"), again = dir.file("again.gif");
  encode(path, 320, 240, 30);
  encode(again, 320, 240, 30);
  CHECK(read_bytes(path) == read_bytes(again));
  const Decoded d = decode(path, 15);
  CHECK(d.codec == "gif");
  CHECK(d.width == 320);
  CHECK(d.height == 240);
  CHECK(d.frames == 30);
  // Delays of 3,4,3,3,4,... cs, the last one set so that the total is exact.
  CHECK(d.duration == Approx(1.0).margin(1e-9));
  // Five colours fit the palette exactly: flat regions come back exact (measured 0;
  // tolerance 1 for the decoder's RGB conversion).
  const Fidelity f = compare_flat(make_frame(320, 240, 15), d.picture);
  for (double m : f.mean) CHECK(m < 1.0);
  CHECK(f.max <= 1);
  const std::string bytes = read_bytes(path);
  CHECK(bytes.find("NETSCAPE2.0") != std::string::npos);  // the looping extension
  check_frames(path, 320, 240, 0);
}

TEST_CASE("GIF: colours that appear later get a new palette", "[video]") {
  // From frame 5 on, a violet block far from the first frame's palette and from the fixed
  // 4x4x4 cube (64 levels from the nearest cube colour) covers 13 % of the picture.
  TempDir dir;
  const std::string path = dir.file("late.gif");
  cb::VideoSettings s;
  s.width = 64, s.height = 48;
  auto sink = cb::open_video(path, s);
  for (int k = 0; k < 10; ++k) {
    Image im(64, 48);
    fill(im, 0, 0, 64, 48, 40, 60, 90);
    if (k >= 5) fill(im, 10, 10, 20, 20, 130, 40, 200);
    sink->push(std::move(im));
  }
  sink->finish();
  const Decoded d = decode(path, 7);
  CHECK(d.frames == 10);
  REQUIRE(d.picture.width == 64);
  const std::uint8_t* block = d.picture.pixel(20, 20);
  const std::uint8_t* background = d.picture.pixel(50, 40);
  CHECK(std::abs(block[0] - 130) <= 1);
  CHECK(std::abs(block[1] - 40) <= 1);
  CHECK(std::abs(block[2] - 200) <= 1);
  CHECK(std::abs(background[0] - 40) <= 1);
  CHECK(std::abs(background[1] - 60) <= 1);
  CHECK(std::abs(background[2] - 90) <= 1);
}

TEST_CASE("GIF palette: exact for few colours, dithers the rest", "[video]") {
  // Left half: four flat colours; right half: a red-green gradient of 8192 colours, far more
  // than a palette holds.
  Image im(256, 128);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 256; ++x) {
      std::uint8_t* p = im.pixel(x, y);
      const bool ramp = x >= 128;
      p[0] = static_cast<std::uint8_t>(ramp ? 2 * (x - 128) : (y < 64 ? 10 : 250));
      p[1] = static_cast<std::uint8_t>(ramp ? 2 * y : (x < 64 ? 20 : 200));
      p[2] = static_cast<std::uint8_t>(ramp ? 128 : 77);
      p[3] = 255;
    }
  cb::gif::Quantizer q(cb::gif::make_palette(im));
  std::vector<std::uint8_t> indices(256 * 128);
  CHECK(q.map(im, indices.data(), 256) == 0.0);  // nothing far from the palette
  auto channel = [&](int x, int y, int c) {
    return static_cast<int>((q.palette()[indices[y * 256 + x]] >> (16 - 8 * c)) & 0xff);
  };
  int wrong_flat = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x)
      for (int c = 0; c < 3; ++c) wrong_flat += channel(x, y, c) != im.pixel(x, y)[c];
  CHECK(wrong_flat == 0);  // flat colours are palette entries: no dithering noise
  // The gradient is dithered: 8x8 tiles average to the input's average within 1 level on
  // the whole (0.78 measured; without dithering ~1.1), and within 8 levels everywhere: the
  // worst tiles lie at the gradient's edge, beyond the outermost palette entries (which
  // are means of boxes of colours), where no mixture of entries can reach.
  double sum = 0, worst = 0;
  int tiles = 0;
  for (int ty = 0; ty < 128; ty += 8)
    for (int tx = 128; tx < 256; tx += 8)
      for (int c = 0; c < 3; ++c) {
        double in = 0, out = 0;
        for (int y = ty; y < ty + 8; ++y)
          for (int x = tx; x < tx + 8; ++x) in += im.pixel(x, y)[c], out += channel(x, y, c);
        sum += std::abs(in - out) / 64, ++tiles;
        worst = std::max(worst, std::abs(in - out) / 64);
      }
  CHECK(sum / tiles < 1.0);
  CHECK(worst < 8.0);
}

TEST_CASE("Video errors: bad extension, missing directory, unfinished file", "[video]") {
  TempDir dir;
  cb::VideoSettings s;
  s.width = 64, s.height = 48;
  CHECK_THROWS_WITH(cb::open_video(dir.file("x.avi"), s),
                    Catch::Contains(".mp4") && Catch::Contains(".webm") && Catch::Contains(".gif"));
  CHECK_THROWS_AS(cb::open_video(dir.file("missing/x.mp4"), s), cb::OutputError);
  // A regular file where a directory should be: fails for root too (unlike chmod).
  std::ofstream(dir.file("plain")) << "x";
  CHECK_THROWS_AS(cb::open_video(dir.file("plain/x.mp4"), s), cb::OutputError);
  if (::geteuid() != 0) {  // root writes anywhere; a read-only directory stops the others
    fs::create_directory(dir.path / "ro");
    fs::permissions(dir.path / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_WITH(cb::open_video(dir.file("ro/x.mp4"), s), Catch::Contains("writable"));
    fs::permissions(dir.path / "ro", fs::perms::owner_all);
    fs::remove(dir.path / "ro");
  }
  s.codec_hint = "vp9";
  CHECK_THROWS_WITH(cb::open_video(dir.file("x.mp4"), s), Catch::Contains("h264"));
  s.codec_hint.clear();
  s.preset = "warp";
  CHECK_THROWS_WITH(cb::open_video(dir.file("x.mp4"), s), Catch::Contains("veryfast"));
  CHECK(dir.names() == std::vector<std::string>{"plain"});  // nothing else was created

  {
    s.preset = "veryfast";
    auto sink = cb::open_video(dir.file("never.mp4"), s);
    for (int k = 0; k < 5; ++k) sink->push(make_frame(64, 48, k));
    // destroyed without finish()
  }
  CHECK(dir.names() == std::vector<std::string>{"plain"});
  {
    auto sink = cb::open_video(dir.file("empty.gif"), s);
    CHECK_THROWS_WITH(sink->finish(), Catch::Contains("no frames"));
  }
  CHECK(dir.names() == std::vector<std::string>{"plain"});

  CHECK(cb::video_codec_name("a/b.MP4") == "h264");
  CHECK(cb::video_codec_name("b.webm") == "vp9");
  CHECK(cb::video_codec_name("b.gif") == "gif");
  CHECK(cb::partial_video_path("out/clip.mp4") == "out/clip.partial.mp4");
}

TEST_CASE("Video: an interrupted run leaves a playable partial file", "[video]") {
  TempDir dir;
  cb::VideoSettings s;
  s.width = 160, s.height = 120;
  cb::VideoEncoder encoder(dir.file("run.mp4"), s);
  for (int k = 0; k < 10; ++k) encoder.push(make_frame(160, 120, k));
  const std::string written = encoder.abort_partial();
  CHECK(written == dir.file("run.partial.mp4"));
  CHECK(dir.names() == std::vector<std::string>{"run.partial.mp4"});
  const Decoded d = decode(written, -1);
  CHECK(d.frames == 10);
  CHECK(d.duration == Approx(10.0 / 30).margin(1e-9));
}

TEST_CASE("Video: a write error (file size limit) leaves nothing behind", "[video]") {
  // A full disk without root: RLIMIT_FSIZE makes write() fail with EFBIG past the limit
  // (with SIGXFSZ ignored), which libavformat reports like ENOSPC.
  TempDir dir;
  rlimit old{};
  REQUIRE(getrlimit(RLIMIT_FSIZE, &old) == 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = old;
  limited.rlim_cur = 64 * 1024;
  REQUIRE(setrlimit(RLIMIT_FSIZE, &limited) == 0);
  std::string message;
  try {
    cb::VideoSettings s;
    s.width = 320, s.height = 240;
    auto sink = cb::open_video(dir.file("big.mp4"), s);
    std::uint32_t seed = 12345;
    for (int k = 0; k < 30; ++k) {
      Image noise(320, 240);  // incompressible: ~100 KB per frame at crf 18
      for (auto& v : noise.rgba)
        v = static_cast<std::uint8_t>((seed = seed * 1664525u + 1013904223u) >> 24);
      sink->push(std::move(noise));
    }
    sink->finish();
  } catch (const cb::OutputError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  INFO(message);
  CHECK(message.find("File too large") != std::string::npos);
  CHECK(message.find("Free some disk space") != std::string::npos);
  CHECK(dir.names().empty());
}

TEST_CASE("Y'CbCr input: MP4 asks for the even size, GIF takes RGBA only", "[video]") {
  TempDir dir;
  cb::VideoSettings settings;
  settings.width = 321, settings.height = 241;
  auto mp4 = cb::open_video(dir.file("a.mp4"), settings);
  const auto size = mp4->yuv420_size();
  REQUIRE(size);
  CHECK(size->width == 322);
  CHECK(size->height == 242);
  cb::Yuv420Image wrong;
  wrong.resize(321, 241);  // the frame's own size, not the coded one
  CHECK_THROWS_AS(mp4->push_yuv420(std::move(wrong)), std::invalid_argument);
  auto gif = cb::open_video(dir.file("a.gif"), settings);
  CHECK_FALSE(gif->yuv420_size());
  cb::Yuv420Image any;
  any.resize(322, 242);
  CHECK_THROWS(gif->push_yuv420(std::move(any)));
}
