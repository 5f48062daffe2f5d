#include "output/video_format.h"

extern "C" {
#include <libavutil/avutil.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
}

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <mutex>

#include "output/output_file.h"

namespace cb::video_detail {

namespace fs = std::filesystem;

namespace {

constexpr Format kFormats[] = {
    {Kind::mp4, ".mp4", "mp4", "libx264", "h264"},
    {Kind::webm, ".webm", "webm", "libvpx-vp9", "vp9"},
    {Kind::gif, ".gif", "gif", "gif", "gif"},
};

}  // namespace

const Format& format_for(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const Format& f : kFormats)
    if (ext == f.extension) return f;
  throw OutputError(path + ": unsupported video extension '" + ext +
                    "'; use .mp4 (H.264), .webm (VP9) or .gif (animated GIF)");
}

namespace {

constexpr const char* kX264Presets[] = {"ultrafast", "superfast", "veryfast", "faster",  "fast",
                                        "medium",    "slow",      "slower",   "veryslow"};

}  // namespace

void check_settings(const std::string& path, const Format& format, const VideoSettings& s) {
  auto fail = [&](const std::string& what) { throw OutputError(path + ": " + what); };
  if (s.width <= 0 || s.height <= 0)
    fail("video size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
         " must be positive");
  if (s.fps <= 0 || s.fps > 1000)
    fail("frame rate " + std::to_string(s.fps) + " must be between 1 and 1000 frames/s");
  if (format.kind == Kind::gif && s.fps > 50)
    fail(
        "GIF stores frame delays in 1/100 s and browsers slow delays under 2/100 s down to "
        "1/10 s, so " +
        std::to_string(s.fps) +
        " frames/s would play too slowly; use 50 frames/s or less "
        "for .gif, or write .mp4");
  if (!s.codec_hint.empty() && s.codec_hint != format.codec && s.codec_hint != format.encoder)
    fail("codec '" + s.codec_hint + "' does not go with " + format.extension +
         " files, which use " + format.codec +
         "; leave the codec empty or change the extension (.mp4: h264, .webm: "
         "vp9, .gif: gif)");
  if (s.crf < 0 || s.crf > 51) fail("x264 crf " + std::to_string(s.crf) + " must be 0..51");
  if (s.vp9_crf < 0 || s.vp9_crf > 63)
    fail("VP9 crf " + std::to_string(s.vp9_crf) + " must be 0..63");
  if (format.kind == Kind::mp4 && std::find(std::begin(kX264Presets), std::end(kX264Presets),
                                            s.preset) == std::end(kX264Presets))
    fail("unknown x264 preset '" + s.preset +
         "'; use one of ultrafast, superfast, veryfast, faster, fast, medium, slow, slower, "
         "veryslow");
  if (s.threads < 0 || s.threads > 64)
    fail("encoder threads " + std::to_string(s.threads) + " must be 0 (default) .. 64");
}

std::string av_text(int err) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(err, text, sizeof text);
  return text;
}

// libav's own messages (x264's banner and statistics) are noise for a command-line user;
// errors still show. Only lowered from libav's default, so a program that chose a level
// keeps it.
void quiet_libav_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_ERROR);
  });
}

std::string temp_name_for(const fs::path& target) {
  static std::atomic<int> counter{0};
  // Hidden, in the target's directory (the rename cannot cross filesystems), unique per
  // process and encoder, and ending in the real extension so tools recognise the format.
  // (Appended piecewise: "." + string trips GCC 12's -Wrestrict false positive.)
  std::string name(".");
  name.append(target.filename().string()).append(".part-").append(std::to_string(::getpid()));
  name.append("-").append(std::to_string(counter++)).append(target.extension().string());
  return (target.parent_path() / name).string();
}

}  // namespace cb::video_detail
