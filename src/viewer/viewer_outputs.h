// The viewer's outputs: "Snapshot" (the frame as a PNG), "Record" (the session as a video
// through cb::VideoEncoder) and "Save scene" (the settings as a scene file, scene_writer.h).
// All are the frame the renderer drew, without the viewer's controls on top.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "output/frame_writer.h"
#include "output/image.h"
#include "scene/scene.h"
#include "viewer/record_clock.h"

namespace cb {

class OutputLock;
class VideoEncoder;

class ViewerOutputs {
 public:
  // Default names go into `out_dir` and start with `scene_name`.
  ViewerOutputs(std::string out_dir, std::string scene_name);
  ~ViewerOutputs();

  // Each returns what to show in the status line ("wrote renders/x.png"); errors a user can
  // cause (an unwritable folder) are caught and returned as the status, not thrown.
  std::string snapshot(const Image& frame, double tau, const std::string& path);
  std::string save(const SceneDesc& scene, const std::string& path);
  // `text` into `path` (the script's `layout`); `what` names it in the status line.
  std::string write_text(const std::string& text, const std::string& path, const char* what);
  // Starts a video of frames of this size at `fps` frames per second. `real_time`: frames
  // are written by wall time (record_clock.h), so the video plays at the speed the session
  // was shown; otherwise (script mode) one video frame per displayed frame.
  std::string start_recording(int width, int height, int fps, const std::string& path,
                              bool real_time);
  std::string stop_recording();
  bool recording() const { return video_ != nullptr; }
  // While recording: the frame displayed at wall time `now` (s), written as often as the
  // video's rate asks (none, once, or repeated; once each when not in real time). MP4 and
  // WebM take it in Y'CbCr at yuv420_size() (Renderer::read_yuv420: no conversion on the
  // encoder's thread, 3 MB instead of 8 at 1080p); GIF only as RGBA (no size).
  void push(Image frame, double now);
  void push(Yuv420Image frame, double now);
  std::optional<PictureSize> yuv420_size() const;
  Yuv420Image spare_yuv420();  // a used picture's memory, to fill again

 private:
  std::string default_path(const std::string& suffix) const;

  std::string out_dir_, scene_name_;
  std::unique_ptr<OutputLock> video_lock_;  // held while recording (output_lock.h)
  std::unique_ptr<VideoEncoder> video_;
  std::string video_path_;
  long long video_frames_ = 0;
  std::optional<RecordClock> clock_;  // real-time recordings: started by the first frame
  bool real_time_ = false;
  // Real time: the picture on screen since the last displayed frame.
  Image shown_rgba_;
  Yuv420Image shown_yuv_;
  template <class Picture, class Push>
  void push_timed(Picture frame, double now, Picture& shown, Push push);
  int video_fps_ = 30;
};

}  // namespace cb
