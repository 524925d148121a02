#pragma once
// A video file written frame by frame through Debian's ffmpeg: H.264 (libx264) in MP4,
// yuv420p (BT.709, tagged) and even dimensions (an odd side is padded by one black row or
// column), moov atom first (+faststart), so that browsers play it. Frames are piped to ffmpeg as raw
// rgb24 as they come; nothing but one row is held.
//
// The file appears whole or not at all: ffmpeg writes a hidden temporary beside it
// (".NAME.XXXXXX") that finish() renames into place; destroying the writer without
// finish() (an error, an exception unwinding) kills ffmpeg and removes the temporary.
#include <filesystem>
#include <string>
#include <vector>

#include <sys/types.h>

#include "testbed/io/image_io.h"

namespace testbed {

struct VideoOptions {
  std::string ffmpeg = "ffmpeg";  // the program, looked up in PATH
  int crf = 18;                   // x264 constant rate factor: 18 is visually lossless for these images
};

class VideoWriter {
 public:
  // `path` must end in .mp4. Starts ffmpeg; throws std::runtime_error naming `path` when it
  // cannot (ffmpeg not installed: the message says to install Debian's ffmpeg package),
  // std::invalid_argument for a bad size, rate or extension.
  VideoWriter(std::filesystem::path path, int width, int height, int fps, VideoOptions options = {});
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame: RGB (3 channels), top-down, the writer's size, values in [0, 1] turned into
  // bytes as PNGs are written (quantize8, image_io.h), so a video frame and the PNG of the
  // same image hold the same bytes. Throws std::invalid_argument for a wrong shape,
  // std::runtime_error naming the file when ffmpeg has failed.
  void addFrame(const ImageF& rgb);
  // Ends the stream, waits for ffmpeg and moves the file into place. Throws
  // std::runtime_error naming the file (with ffmpeg's last message) when ffmpeg failed.
  void finish();

  int frames() const { return frames_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(const std::string& what);
  std::string ffmpegMessage() const;
  void abandon() noexcept;

  std::filesystem::path path_, temporary_;
  int width_, height_;
  int frames_ = 0;
  int pipe_ = -1;       // write end of ffmpeg's stdin
  int stderrFd_ = -1;   // an unlinked temporary file holding ffmpeg's messages
  pid_t pid_ = -1;
  std::vector<unsigned char> row_;
};

}  // namespace testbed
