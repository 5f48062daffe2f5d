// How many video frames "Record" writes for one displayed frame, so that a recording plays
// at the speed the session was shown. The window shows frames when it can (55-75 a second at
// 1080p here, fewer on a busy machine) while the video has a fixed rate (the scene's fps):
// by wall time, a displayed frame stands for the video frames whose times have come since
// the last one; none when the window runs ahead of the video's rate, several when it falls
// behind (the picture that was on screen for the earlier ones, the new one for the last:
// viewer_outputs.cpp). In script mode every displayed frame advances the
// physics by exactly one video frame, so the clock is not used: one frame each.
#pragma once

namespace cb {

class RecordClock {
 public:
  // `fps`: the video's frame rate; `start`: wall time (s) of the first displayed frame.
  RecordClock(int fps, double start) : fps_(fps), start_(start) {}
  // Video frames to write for the frame displayed at wall time `now` (>= the previous one).
  // At most `fps` at once: a window stalled for longer (a dialog, a suspended process)
  // freezes the picture for one second of video, not for the whole stall.
  int frames_at(double now);
  long long written() const { return written_; }

 private:
  int fps_;
  double start_;
  long long written_ = 0;
};

}  // namespace cb
