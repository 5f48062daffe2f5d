#include "viewer/viewer_outputs.h"

#include <cstdio>
#include <filesystem>

#include "output/output_file.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "output/video_encoder.h"
#include "scene/scene_writer.h"

namespace cb {

ViewerOutputs::ViewerOutputs(std::string out_dir, std::string scene_name)
    : out_dir_(std::move(out_dir)), scene_name_(std::move(scene_name)) {}

ViewerOutputs::~ViewerOutputs() {
  if (video_) stop_recording();  // a window closed while recording still leaves a whole video
}

std::string ViewerOutputs::default_path(const std::string& suffix) const {
  std::error_code ignored;
  std::filesystem::create_directories(out_dir_, ignored);  // made on demand, as `render` does
  return (std::filesystem::path(out_dir_) / (scene_name_ + suffix)).string();
}

std::string ViewerOutputs::snapshot(const Image& frame, double tau, const std::string& path) {
  char suffix[64];
  std::snprintf(suffix, sizeof suffix, "_view_tau_%010.3f.png", tau);
  const std::string target = path.empty() ? default_path(suffix) : path;
  try {
    write_png(target, frame);
  } catch (const OutputError& e) {
    return std::string("snapshot failed: ") + e.what();
  }
  std::printf("%s\n", target.c_str());  // for scripts, as `snapshot` prints its files
  std::fflush(stdout);
  return "wrote " + target;
}

std::string ViewerOutputs::save(const SceneDesc& scene, const std::string& path) {
  const std::string target = path.empty() ? default_path("_view.toml") : path;
  try {
    OutputFile out(target);
    out.write(write_scene(scene));
    out.commit();
  } catch (const OutputError& e) {
    return std::string("save failed: ") + e.what();
  }
  std::printf("%s\n", target.c_str());
  std::fflush(stdout);
  return "wrote " + target;
}

std::string ViewerOutputs::write_text(const std::string& text, const std::string& path,
                                      const char* what) {
  try {
    OutputFile out(path);
    out.write(text);
    out.commit();
  } catch (const OutputError& e) {
    return std::string(what) + " failed: " + e.what();
  }
  return "wrote " + path;
}

std::string ViewerOutputs::start_recording(int width, int height, int fps, const std::string& path,
                                           bool real_time) {
  if (video_) return "already recording " + video_path_;
  video_path_ = path.empty() ? default_path("_view.mp4") : path;
  VideoSettings settings;
  settings.width = width;
  settings.height = height;
  settings.fps = fps;
  video_fps_ = fps;
  try {
    // Before the encoder makes its temporary file: a render to the same video refuses us.
    video_lock_ = std::make_unique<OutputLock>(OutputLock::video_lock_name(video_path_));
    video_ = std::make_unique<VideoEncoder>(video_path_, settings);
  } catch (const std::exception& e) {
    video_lock_.reset();
    return std::string("record failed: ") + e.what();
  }
  video_frames_ = 0;
  clock_.reset();
  shown_rgba_ = Image();
  shown_yuv_ = Yuv420Image();
  real_time_ = real_time;
  return "recording " + video_path_ + " (M or Record stops)";
}

std::string ViewerOutputs::stop_recording() {
  if (!video_) return {};
  std::string status;
  try {
    video_->finish();
    status = "wrote " + video_path_ + " (" + std::to_string(video_frames_) + " frames)";
    std::printf("%s\n", video_path_.c_str());
    std::fflush(stdout);
  } catch (const std::exception& e) {
    status = std::string("record failed: ") + e.what();
  }
  video_.reset();
  video_lock_.reset();  // after the video is in place
  return status;
}

// The video frames whose times came since the last displayed frame showed the picture that
// was on screen then (`shown`); only the newest one shows this frame (record_clock.h).
template <class Picture, class Push>
void ViewerOutputs::push_timed(Picture frame, double now, Picture& shown, Push push) {
  if (!real_time_) {
    push(std::move(frame));
    ++video_frames_;
    return;
  }
  if (!clock_) clock_.emplace(video_fps_, now);
  const int due = clock_->frames_at(now);
  const bool have_shown = shown.width > 0;
  for (int k = 0; k + 1 < due; ++k) {
    push(have_shown ? shown : frame);
    ++video_frames_;
  }
  if (due > 0) {
    push(frame);
    ++video_frames_;
  }
  shown = std::move(frame);
}

void ViewerOutputs::push(Image frame, double now) {
  if (!video_) return;
  push_timed(std::move(frame), now, shown_rgba_, [this](Image p) { video_->push(std::move(p)); });
}

std::optional<PictureSize> ViewerOutputs::yuv420_size() const {
  return video_ ? video_->yuv420_size() : std::nullopt;
}

Yuv420Image ViewerOutputs::spare_yuv420() {
  return video_ ? video_->spare_yuv420() : Yuv420Image();
}

void ViewerOutputs::push(Yuv420Image frame, double now) {
  if (!video_) return;
  push_timed(std::move(frame), now, shown_yuv_,
             [this](Yuv420Image p) { video_->push_yuv420(std::move(p)); });
}

}  // namespace cb
