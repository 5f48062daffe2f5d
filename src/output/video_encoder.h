// Video files from rendered frames, in-process with libavcodec/libavformat: H.264 in MP4,
// VP9 in WebM or an animated GIF, chosen by the file's extension.
//
// Why in-process and on a thread: at 1080p the encoder is the slowest stage of the program
// (PLATFORM-NOTES: x264 veryfast ~66 fps against ~300+ fps for rendering), and a pipe to an
// ffmpeg process carries only ~75 RGBA frames/s. push() only queues the image; colour
// conversion and encoding run on a worker thread behind a small bounded queue, so rendering
// the next frame overlaps with encoding this one.
//
// Guarantees:
// - Exact timing: time base 1/fps and pts = frame index, so N frames last exactly N/fps s
//   in MP4. Containers with coarser clocks round each frame's start, never accumulating
//   error: WebM counts milliseconds, GIF centiseconds (3,4,3,3,4,... cs at 30 fps, with the
//   last delay chosen so that the total is right).
// - Reproducible: the same frames and settings give a byte-identical file (bit-exact
//   flags, no creation time or library version in the container, a fixed x264 thread count).
//   The H.264 stream still carries x264's own version SEI, fixed for a given libx264 build.
// - Whole or nothing: data goes to a hidden temporary file beside the target and is renamed
//   to the requested name only by finish(); a failure or a destructor without finish()
//   leaves nothing under the requested name.
// - Odd sizes never fail: H.264 4:2:0 needs even dimensions, so MP4 pads one column and/or
//   row by repeating the edge pixels (the video is then 1 px larger; nothing is cropped).
//   VP9 and GIF keep the size as it is.
// - Colour: yuv420p, BT.709 matrix, primaries and transfer, limited range, tagged in the
//   stream (one convention for every size; renders are sRGB, whose primaries are BT.709).
#pragma once

#include <memory>
#include <string>

#include "output/frame_writer.h"
#include "output/image.h"

namespace cb {

struct VideoSettings {
  int width = 0, height = 0;  // of every pushed image
  int fps = 30;               // frames per second (integer: frame k is at k/fps s exactly)
  // "" picks the codec from the extension; otherwise it must name that codec ("h264",
  // "vp9", "gif", or the encoder "libx264", "libvpx-vp9"): a guard against surprises.
  std::string codec_hint;
  int crf = 18;      // x264 constant rate factor: 18 is visually lossless for flat graphics
  int vp9_crf = 32;  // libvpx-vp9 constant quality (with bit rate 0), its usual default
  // x264 preset. "veryfast" for lecture clips: flat shading and thin lines compress well
  // with any preset. Measured through this sink at 1080p on the 2-vCPU machine (synthetic
  // frames: flat background, 200 moving squares, a gradient panel; 120 frames): ultrafast
  // 93 fps / 1605 KB, veryfast 66 fps / 340 KB, medium 44 fps / 317 KB. So veryfast is
  // ~1.5x faster than medium for a ~7 % larger file; ultrafast (no CABAC, no deblocking)
  // buys another 1.4x with a 4.7x larger file.
  std::string preset = "veryfast";
  // Encoder threads. 0 means a fixed 2, not "all cores": x264's output depends on its
  // thread count, so a fixed number keeps files identical from machine to machine (on 2
  // vCPUs, 3 threads were no faster). Larger values help on bigger machines.
  int threads = 0;
  int queue = 3;  // frames waiting for the encoder (1080p: 8 MB as RGBA, 3 MB as Y'CbCr)
};

class VideoEncoder : public FrameSink {
 public:
  // Opens the encoder and the temporary file at once, so a missing encoder, an unwritable
  // directory or an unsupported extension is reported (OutputError, with the fix) before
  // any frame is rendered.
  VideoEncoder(std::string path, VideoSettings settings);
  ~VideoEncoder() override;  // without finish(): stops, removes the temporary file
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Queues the image (moved, not copied); blocks only while the queue is full. Throws the
  // worker's first error (OutputError), e.g. a full disk.
  void push(Image image) override;
  // MP4 and WebM also take Y'CbCr 4:2:0 pictures converted by the caller (output/yuv420.h)
  // at this size (the frame's, padded to even for H.264): the encoder reads them in place
  // (no copy, no conversion on its thread). GIF takes RGBA only.
  std::optional<PictureSize> yuv420_size() const override;
  void push_yuv420(Yuv420Image image) override;
  Yuv420Image spare_yuv420() override;
  // Encodes what is queued, flushes the encoder, completes the container and renames it to
  // the requested path. Throws OutputError; then no file is left at the requested path.
  void finish() override;
  // For an interrupted run (Ctrl-C): completes the container with the frames pushed so far
  // (still queued ones included) and renames it to `partial_path`, by default
  // partial_video_path(path), so it plays but cannot be mistaken for a finished video.
  // Returns the path written, or "" if no frame had been pushed (then nothing is written;
  // finish() throws OutputError in that case). Not async-signal-safe: let the signal
  // handler set a flag and call this from the thread that pushes frames. Throws
  // OutputError like finish().
  std::string abort_partial(const std::string& partial_path = {});

  const std::string& path() const;
  long long frames_pushed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A VideoEncoder for `path` (.mp4, .webm or .gif); throws OutputError for any other
// extension, listing the supported ones.
std::unique_ptr<FrameSink> open_video(const std::string& path, const VideoSettings& settings);

// The codec a path's extension selects, for a JSON sidecar: "h264", "vp9" or "gif";
// throws OutputError for an unsupported extension.
std::string video_codec_name(const std::string& path);

// "dir/name.mp4" -> "dir/name.partial.mp4": where abort_partial() puts its file.
std::string partial_video_path(const std::string& path);

}  // namespace cb
