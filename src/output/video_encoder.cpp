// The video encoder behind VideoEncoder (see the header for what it guarantees).
//
// Sections: Impl (opening, the worker thread, encoding one frame, completing the file); the
// public functions. The formats, the settings check and the libav helpers: video_format.h.
#include "output/video_encoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <variant>
#include <vector>

#include "output/gif_palette.h"
#include "output/output_file.h"
#include "output/video_format.h"

namespace cb {

namespace {

namespace fs = std::filesystem;
using namespace video_detail;

}  // namespace

// ---- Impl -------------------------------------------------------------------------------------

struct VideoEncoder::Impl {
  std::string path, temp;
  const Format* format = nullptr;
  VideoSettings settings;
  int coded_width = 0, coded_height = 0;  // the padded size for H.264

  AVFormatContext* mux = nullptr;
  AVStream* stream = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;
  AVFrame* lent = nullptr;  // wraps a pushed Yuv420Image (send_yuv)
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  std::vector<std::uint8_t> padded;  // odd-sized RGBA frames, padded to the coded size
  std::unique_ptr<gif::Quantizer> quantizer;
  std::int64_t next_pts = 0;

  std::deque<std::variant<Image, Yuv420Image>> queue;
  // Encoded Y'CbCr pictures, handed back by spare_yuv420() for the next frame: reusing
  // their memory spares a 3 MB allocation and its page faults per 1080p frame.
  std::vector<Yuv420Image> spares;
  std::size_t capacity = 3;
  std::mutex mutex;
  std::condition_variable ready, space;
  bool closing = false, discard = false, done = false;
  std::exception_ptr error;
  std::thread worker;
  long long pushed = 0;

  void open();
  void open_codec();
  void work();
  void encode(std::variant<Image, Yuv420Image>& picture);
  void send_yuv(Yuv420Image&& image);
  void convert_yuv(const Image& image);
  void convert_gif(const Image& image);
  void send(const AVFrame* input);
  void stop_worker(bool drop_queued);
  std::int64_t end_time(std::int64_t pts) const;  // end of frame `pts`, in the stream's units
  void complete();  // flush, trailer, close: the temporary file is then a whole video
  std::string commit(const std::string& target, bool partial);
  void release();
  void remove_temp();

  template <class Picture>
  void enqueue(Picture&& picture) {
    std::unique_lock lock(mutex);
    if (closing) throw std::logic_error("VideoEncoder::push after finish()");
    space.wait(lock, [this] { return queue.size() < capacity || error; });
    if (error) std::rethrow_exception(error);
    queue.emplace_back(std::forward<Picture>(picture));
    ++pushed;
    lock.unlock();
    ready.notify_one();
  }

  [[noreturn]] void write_failed(int err) const {
    throw OutputError(path + ": writing the video failed (" + av_text(err) +
                      "); nothing was written under that name. Free some disk space or choose "
                      "another directory");
  }
};

void VideoEncoder::Impl::open() {
  check_output_path(path, std::string("out") + format->extension);
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  temp = temp_name_for(dir / target.filename());

  int err = avformat_alloc_output_context2(&mux, nullptr, format->muxer, temp.c_str());
  if (err < 0 || !mux)
    throw OutputError(path + ": this FFmpeg build has no " + format->muxer + " muxer (" +
                      av_text(err) + "); install the full libavformat or choose another format");
  open_codec();

  err = avio_open(&mux->pb, temp.c_str(), AVIO_FLAG_WRITE);
  if (err < 0)
    throw OutputError(path + ": cannot write in " + dir.string() + " (" + av_text(err) +
                      "); choose a writable directory");
  AVDictionary* options = nullptr;
  // Bit-exact muxing: no "encoder" tag with the library version, no creation time.
  av_dict_set(&options, "fflags", "+bitexact", 0);
  if (format->kind == Kind::mp4) av_dict_set(&options, "movflags", "+faststart", 0);
  if (format->kind == Kind::gif) av_dict_set(&options, "loop", "0", 0);  // 0: forever
  err = avformat_write_header(mux, &options);
  av_dict_free(&options);
  if (err < 0) write_failed(err);
}

void VideoEncoder::Impl::open_codec() {
  const AVCodec* encoder = avcodec_find_encoder_by_name(format->encoder);
  if (!encoder)
    throw OutputError(
        path + ": this FFmpeg build has no " + format->encoder + " encoder, needed for " +
        format->extension + " files; install libavcodec with " + format->encoder +
        " (Debian's libavcodec59 has it) or write another format (.mp4, .webm, .gif)");
  const VideoSettings& s = settings;
  const bool yuv = format->kind != Kind::gif;
  // H.264 4:2:0 needs even sizes: pad by one pixel (see convert_yuv). VP9 codes odd sizes.
  coded_width = format->kind == Kind::mp4 ? (s.width + 1) & ~1 : s.width;
  coded_height = format->kind == Kind::mp4 ? (s.height + 1) & ~1 : s.height;

  codec = avcodec_alloc_context3(encoder);
  packet = av_packet_alloc();
  frame = av_frame_alloc();
  lent = av_frame_alloc();
  if (!lent) throw std::bad_alloc();
  if (!codec || !packet || !frame) throw std::bad_alloc();
  codec->width = coded_width;
  codec->height = coded_height;
  codec->sample_aspect_ratio = AVRational{1, 1};
  codec->time_base = AVRational{1, s.fps};  // pts = frame index: exact timing
  codec->framerate = AVRational{s.fps, 1};
  codec->pix_fmt = yuv ? AV_PIX_FMT_YUV420P : AV_PIX_FMT_PAL8;
  codec->flags |= AV_CODEC_FLAG_BITEXACT;
  if (mux->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  // A fixed thread count: x264's output depends on it (header: threads).
  codec->thread_count = s.threads > 0 ? s.threads : 2;
  if (yuv) {
    // A key frame every 2 s: lecture players seek to key frames.
    codec->gop_size = 2 * s.fps;
    codec->color_range = AVCOL_RANGE_MPEG;
    codec->color_primaries = AVCOL_PRI_BT709;
    codec->color_trc = AVCOL_TRC_BT709;
    codec->colorspace = AVCOL_SPC_BT709;
    // Each chroma sample is its 2x2 block's mean (output/yuv420.h; swscale's same-size
    // conversion scales the chroma planes the same way): centred, not H.264's default left
    // siting, which would shift colour edges by half a pixel in players that honour it.
    codec->chroma_sample_location = AVCHROMA_LOC_CENTER;
  }

  AVDictionary* options = nullptr;
  if (format->kind == Kind::mp4) {
    av_dict_set(&options, "preset", s.preset.c_str(), 0);
    av_dict_set_int(&options, "crf", s.crf, 0);
  } else if (format->kind == Kind::webm) {
    // Constant quality (crf with bit rate 0) at libvpx's real-time speed: the fastest VP9
    // there is (~43 fps at 1080p here), with rows encoded in parallel.
    codec->bit_rate = 0;
    av_dict_set_int(&options, "crf", s.vp9_crf, 0);
    av_dict_set(&options, "deadline", "realtime", 0);
    av_dict_set_int(&options, "cpu-used", 8, 0);
    av_dict_set_int(&options, "row-mt", 1, 0);
  }
  const int err = avcodec_open2(codec, encoder, &options);
  av_dict_free(&options);
  if (err < 0)
    throw OutputError(path + ": cannot open the " + format->encoder + " encoder for " +
                      std::to_string(coded_width) + "x" + std::to_string(coded_height) + " at " +
                      std::to_string(s.fps) + " frames/s (" + av_text(err) +
                      "); try a smaller size or another format");

  frame->format = codec->pix_fmt;
  frame->width = coded_width;
  frame->height = coded_height;
  if (av_frame_get_buffer(frame, 0) < 0) throw std::bad_alloc();

  stream = avformat_new_stream(mux, nullptr);
  if (!stream) throw std::bad_alloc();
  stream->time_base = codec->time_base;
  stream->avg_frame_rate = stream->r_frame_rate = codec->framerate;
  if (avcodec_parameters_from_context(stream->codecpar, codec) < 0) throw std::bad_alloc();

  if (yuv) {
    // No scaling, only RGB -> Y'CbCr: accurate rounding and bit-exact arithmetic keep the
    // output identical everywhere; bilinear filtering is what the 2x chroma reduction uses.
    sws = sws_getContext(coded_width, coded_height, AV_PIX_FMT_RGBA, coded_width, coded_height,
                         AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_BITEXACT,
                         nullptr, nullptr, nullptr);
    if (!sws) throw std::bad_alloc();
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    // Source: full-range RGB; destination: BT.709 limited range, as tagged above.
    sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }
}

void VideoEncoder::Impl::work() {
  for (;;) {
    std::variant<Image, Yuv420Image> picture;
    {
      std::unique_lock lock(mutex);
      ready.wait(lock, [this] { return !queue.empty() || closing; });
      if (queue.empty()) return;
      picture = std::move(queue.front());
      queue.pop_front();
    }
    space.notify_one();
    {
      std::lock_guard lock(mutex);
      if (error || discard) continue;  // after a failure: drain without work
    }
    try {
      encode(picture);
    } catch (...) {
      std::lock_guard lock(mutex);
      error = std::current_exception();
      space.notify_all();
    }
  }
}

void VideoEncoder::Impl::encode(std::variant<Image, Yuv420Image>& picture) {
  if (auto* yuv = std::get_if<Yuv420Image>(&picture)) return send_yuv(std::move(*yuv));
  // The encoder may still hold the previous frame (the GIF encoder keeps it to find what
  // changed): make_writable then gives this frame fresh buffers instead of overwriting.
  const int err = av_frame_make_writable(frame);
  if (err < 0) throw std::bad_alloc();
  const Image& image = std::get<Image>(picture);
  if (format->kind == Kind::gif)
    convert_gif(image);
  else
    convert_yuv(image);
  frame->pts = next_pts++;
  send(frame);
}

namespace {
// A Y'CbCr picture lent to libavcodec: when its last reference goes, its memory returns to
// the encoder's spares for the next frame.
struct Lent {
  std::mutex* mutex;
  std::vector<Yuv420Image>* spares;
  std::size_t keep;
  Yuv420Image image;
};
void give_back(void* opaque, std::uint8_t*) {
  std::unique_ptr<Lent> lent(static_cast<Lent*>(opaque));
  std::lock_guard lock(*lent->mutex);
  if (lent->spares->size() < lent->keep) lent->spares->push_back(std::move(lent->image));
}
}  // namespace

// Already converted (output/yuv420.h, on the rendering thread): the encoder reads the
// picture where it is, without a copy (x264 and libvpx copy it into their own frames).
void VideoEncoder::Impl::send_yuv(Yuv420Image&& image) {
  auto held = std::make_unique<Lent>(Lent{&mutex, &spares, capacity + 1, std::move(image)});
  Yuv420Image& p = held->image;
  AVBufferRef* buffer = av_buffer_create(p.bytes.data(), p.bytes.size(), give_back, held.get(), 0);
  if (!buffer) throw std::bad_alloc();
  held.release();  // the buffer owns it now
  av_frame_unref(lent);
  lent->buf[0] = buffer;
  lent->format = codec->pix_fmt;
  lent->width = coded_width;
  lent->height = coded_height;
  for (int k = 0; k < 3; ++k) {
    lent->data[k] = p.plane(k);
    lent->linesize[k] = k == 0 ? p.luma_stride : p.chroma_stride();
  }
  lent->pts = next_pts++;
  send(lent);
  av_frame_unref(lent);  // libavcodec holds its own reference for as long as it needs one
}

void VideoEncoder::Impl::convert_yuv(const Image& image) {
  const std::uint8_t* src[1] = {image.rgba.data()};
  int src_stride[1] = {image.width * 4};
  if (coded_width != image.width || coded_height != image.height) {
    // Odd size (H.264 only): pad the RGBA picture by repeating its last column and row, then
    // convert at the even size. (Converting at the odd size and padding afterwards is not
    // enough: swscale's last chroma sample of an odd-width row mixes in a pixel that does
    // not exist.) Costs one copy of the frame, only for odd sizes.
    const std::size_t row_bytes = static_cast<std::size_t>(coded_width) * 4;
    padded.resize(row_bytes * coded_height);
    for (int y = 0; y < coded_height; ++y) {
      const std::uint8_t* from = image.pixel(0, std::min(y, image.height - 1));
      std::uint8_t* to = padded.data() + row_bytes * y;
      std::memcpy(to, from, static_cast<std::size_t>(image.width) * 4);
      if (coded_width != image.width)
        std::memcpy(to + image.width * 4, to + (image.width - 1) * 4, 4);
    }
    src[0] = padded.data();
    src_stride[0] = static_cast<int>(row_bytes);
  }
  sws_scale(sws, src, src_stride, 0, coded_height, frame->data, frame->linesize);
}

void VideoEncoder::Impl::convert_gif(const Image& image) {
  if (!quantizer) quantizer = std::make_unique<gif::Quantizer>(gif::make_palette(image));
  // More than 1 % of the picture far from every palette colour: new colours have come, so
  // make a new palette from this frame (costlier frames from here on; gif_palette.h).
  if (quantizer->map(image, frame->data[0], frame->linesize[0]) > 0.01) {
    quantizer = std::make_unique<gif::Quantizer>(gif::make_palette(image));
    quantizer->map(image, frame->data[0], frame->linesize[0]);
  }
  std::memcpy(frame->data[1], quantizer->palette().data(), AVPALETTE_SIZE);
}

// Sends one frame (nullptr: end of stream) and writes every packet the encoder has ready.
void VideoEncoder::Impl::send(const AVFrame* input) {
  int err = avcodec_send_frame(codec, input);
  if (err < 0)
    throw OutputError(path + ": the " + std::string(format->encoder) + " encoder failed (" +
                      av_text(err) + ")");
  for (;;) {
    err = avcodec_receive_packet(codec, packet);
    if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
    if (err < 0)
      throw OutputError(path + ": the " + std::string(format->encoder) + " encoder failed (" +
                        av_text(err) + ")");
    packet->stream_index = stream->index;
    // Muxers pick their own time base (MP4 1/15360, WebM 1/1000, GIF 1/100). Each packet is
    // one frame; its duration is the difference of rounded times, so the durations add up
    // to the rounded total and never drift.
    const std::int64_t pts = packet->pts;
    av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->duration = end_time(pts) - av_rescale_q(pts, codec->time_base, stream->time_base);
    err = av_interleaved_write_frame(mux, packet);  // takes the packet's data
    if (err < 0) write_failed(err);
  }
}

void VideoEncoder::Impl::stop_worker(bool drop_queued) {
  {
    std::lock_guard lock(mutex);
    closing = true;
    if (drop_queued) {
      discard = true;
      queue.clear();
    }
  }
  ready.notify_all();
  space.notify_all();
  if (worker.joinable()) worker.join();
}

std::int64_t VideoEncoder::Impl::end_time(std::int64_t pts) const {
  return av_rescale_q(pts + 1, codec->time_base, stream->time_base);
}

void VideoEncoder::Impl::complete() {
  send(nullptr);  // flush: x264 holds frames for look-ahead and B-frames
  if (format->kind == Kind::gif && next_pts > 0) {
    // The GIF muxer gives the last frame the previous frame's delay unless told otherwise
    // (3 or 4 cs at 30 fps): tell it the delay that makes the total exact.
    const std::int64_t last = end_time(next_pts - 1) - end_time(next_pts - 2);
    av_opt_set_int(mux->priv_data, "final_delay", last, 0);
  }
  int err = av_write_trailer(mux);
  if (err < 0) write_failed(err);
  if (mux->pb->error < 0) write_failed(mux->pb->error);
  err = avio_closep(&mux->pb);
  if (err < 0) write_failed(err);
  // Durable before it gets its name, like OutputFile::commit.
  const int fd = ::open(temp.c_str(), O_RDONLY);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int e = errno;
    if (fd >= 0) ::close(fd);
    write_failed(AVERROR(e));
  }
  ::close(fd);
}

std::string VideoEncoder::Impl::commit(const std::string& target, bool partial) {
  if (done) throw std::logic_error("VideoEncoder: finish() or abort_partial() called twice");
  done = true;
  try {
    stop_worker(false);
    if (error) std::rethrow_exception(error);
    if (next_pts == 0) {
      // A container without frames is no video (and some muxers refuse it).
      release();
      remove_temp();
      if (partial) return {};
      throw OutputError(path + ": no frames were given, so no video was written");
    }
    complete();
    if (std::rename(temp.c_str(), target.c_str()) != 0)
      throw OutputError(target + ": cannot rename the finished video into place (" +
                        std::strerror(errno) + ")");
    temp.clear();
  } catch (...) {
    release();
    remove_temp();
    throw;
  }
  release();
  return target;
}

void VideoEncoder::Impl::release() {
  sws_freeContext(sws);
  sws = nullptr;
  av_frame_free(&frame);
  av_frame_free(&lent);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  if (mux) {
    if (mux->pb) avio_closep(&mux->pb);
    avformat_free_context(mux);
    mux = nullptr;
  }
  quantizer.reset();
}

void VideoEncoder::Impl::remove_temp() {
  if (!temp.empty()) std::remove(temp.c_str());
  temp.clear();
}

// ---- VideoEncoder -----------------------------------------------------------------------------

VideoEncoder::VideoEncoder(std::string path, VideoSettings settings) : impl_(new Impl) {
  quiet_libav_once();
  Impl& d = *impl_;
  d.path = std::move(path);
  d.format = &format_for(d.path);
  check_settings(d.path, *d.format, settings);
  d.settings = std::move(settings);
  d.capacity = static_cast<std::size_t>(std::max(1, d.settings.queue));
  try {
    d.open();
  } catch (...) {
    d.release();
    d.remove_temp();
    throw;
  }
  d.worker = std::thread([&d] { d.work(); });
}

VideoEncoder::~VideoEncoder() {
  if (impl_->done) return;
  impl_->stop_worker(true);
  impl_->release();
  impl_->remove_temp();
}

void VideoEncoder::push(Image image) {
  Impl& d = *impl_;
  if (image.width != d.settings.width || image.height != d.settings.height ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::invalid_argument("VideoEncoder::push: a " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " image for a " +
                                std::to_string(d.settings.width) + "x" +
                                std::to_string(d.settings.height) + " video");
  d.enqueue(std::move(image));
}

std::optional<PictureSize> VideoEncoder::yuv420_size() const {
  if (impl_->format->kind == Kind::gif) return std::nullopt;
  return PictureSize{impl_->coded_width, impl_->coded_height};
}

Yuv420Image VideoEncoder::spare_yuv420() {
  std::lock_guard lock(impl_->mutex);
  if (impl_->spares.empty()) return {};
  Yuv420Image spare = std::move(impl_->spares.back());
  impl_->spares.pop_back();
  return spare;
}

void VideoEncoder::push_yuv420(Yuv420Image image) {
  Impl& d = *impl_;
  if (d.format->kind == Kind::gif || image.width != d.coded_width ||
      image.height != d.coded_height || image.luma_stride < image.width ||
      image.luma_stride % 2 != 0 || image.bytes.size() != image.plane_offset(3))
    throw std::invalid_argument("VideoEncoder::push_yuv420: a " + std::to_string(image.width) +
                                "x" + std::to_string(image.height) +
                                " Y'CbCr picture where yuv420_size() asks for another");
  d.enqueue(std::move(image));
}

void VideoEncoder::finish() {
  if (impl_->done) return;
  impl_->commit(impl_->path, false);
}

std::string VideoEncoder::abort_partial(const std::string& partial_path) {
  return impl_->commit(partial_path.empty() ? partial_video_path(impl_->path) : partial_path, true);
}

const std::string& VideoEncoder::path() const {
  return impl_->path;
}

long long VideoEncoder::frames_pushed() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->pushed;
}

// ---- free functions -----------------------------------------------------------------------

std::unique_ptr<FrameSink> open_video(const std::string& path, const VideoSettings& settings) {
  return std::make_unique<VideoEncoder>(path, settings);
}

std::string video_codec_name(const std::string& path) {
  return format_for(path).codec;
}

std::string partial_video_path(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

}  // namespace cb
