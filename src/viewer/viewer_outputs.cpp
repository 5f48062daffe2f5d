#include "viewer/viewer_outputs.h"

#include <cstdio>
#include <filesystem>

#include "output/output_file.h"
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
    video_ = std::make_unique<VideoEncoder>(video_path_, settings);
  } catch (const std::exception& e) {
    return std::string("record failed: ") + e.what();
  }
  video_frames_ = 0;
  clock_.reset();
  shown_ = Image();
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
  return status;
}

void ViewerOutputs::push(Image frame, double now) {
  if (!video_) return;
  if (!real_time_) {
    video_->push(std::move(frame));
    ++video_frames_;
    return;
  }
  if (!clock_) clock_.emplace(video_fps_, now);
  // The video frames whose times came since the last displayed frame showed the picture that
  // was on screen then (`shown_`); only the newest one shows this frame.
  const int due = clock_->frames_at(now);
  for (int k = 0; k + 1 < due; ++k) {
    video_->push(shown_.rgba.empty() ? frame : shown_);
    ++video_frames_;
  }
  if (due > 0) {
    video_->push(frame);
    ++video_frames_;
  }
  shown_ = std::move(frame);
}

}  // namespace cb
