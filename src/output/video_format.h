// What VideoEncoder needs before it opens anything: the formats it writes (by extension),
// the check of its settings, the name of its temporary file, and two libav helpers.
// Internal to cb_output (video_encoder.cpp, video_format.cpp).
#pragma once

#include <filesystem>
#include <string>

#include "output/video_encoder.h"

namespace cb::video_detail {

enum class Kind { mp4, webm, gif };

struct Format {
  Kind kind;
  const char* extension;
  const char* muxer;
  const char* encoder;  // libavcodec encoder name
  const char* codec;    // codec name for sidecars and codec_hint
};

// The format an extension (any case) selects; throws OutputError naming the supported ones.
const Format& format_for(const std::string& path);
// Throws OutputError naming the setting and its valid range.
void check_settings(const std::string& path, const Format& format, const VideoSettings& s);
// libav's text for an error code.
std::string av_text(int err);
// Lowers libav's log level from its default (INFO) to errors, once per process.
void quiet_libav_once();
// A hidden, unique temporary name beside `target`, ending in its extension.
std::string temp_name_for(const std::filesystem::path& target);

}  // namespace cb::video_detail
