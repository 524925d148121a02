#include "testbed/io/video_writer.h"
#include "testbed/io/file_extension.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace testbed {
namespace {

std::string errnoText(int error) { return std::strerror(error); }

// A write to a pipe whose reader died raises SIGPIPE, which would end the process before
// the error could be reported. The signal is blocked in this thread for the write, and a
// SIGPIPE it caused is taken off the pending set before the old mask comes back.
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigemptyset(&pipeSet_);
    sigaddset(&pipeSet_, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipeSet_, &old_);
  }
  ~SigpipeBlock() {
    if (!wasPending_) {
      const timespec zero{0, 0};
      while (sigtimedwait(&pipeSet_, nullptr, &zero) == SIGPIPE) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlock(const SigpipeBlock&) = delete;
  SigpipeBlock& operator=(const SigpipeBlock&) = delete;

 private:
  sigset_t pipeSet_, old_;
  bool wasPending_ = false;
};

// Writes all of `size` bytes; returns 0 or the errno of the failure.
int writeAll(int fd, const unsigned char* data, std::size_t size) {
  SigpipeBlock block;
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += n;
    size -= std::size_t(n);
  }
  return 0;
}

}  // namespace

VideoWriter::VideoWriter(std::filesystem::path path, int width, int height, int fps, VideoOptions options)
    : path_(std::move(path)), width_(width), height_(height) {
  const std::string name = path_.string();
  if (lowerExtension(path_) != ".mp4") throw std::invalid_argument(name + ": a video must end in .mp4");
  if (width < 1 || height < 1 || fps < 1)
    throw std::invalid_argument(name + ": video size " + std::to_string(width) + "x" + std::to_string(height) +
                                " at " + std::to_string(fps) + " fps, expected positive values");
  row_.resize(std::size_t(width) * 3);

  // Appended piecewise: `"." + string` trips GCC 12's -Wrestrict false positive.
  std::string hidden = ".";
  hidden += path_.filename().string();
  hidden += ".XXXXXX";
  std::string pattern = (path_.parent_path() / hidden).string();
  const int tempFd = ::mkstemp(pattern.data());
  if (tempFd < 0) throw std::runtime_error(name + ": cannot create a temporary beside it: " + errnoText(errno));
  // Only the name is reserved: ffmpeg creates the file anew, with the umask's mode rather
  // than mkstemp's 0600.
  ::close(tempFd);
  ::unlink(pattern.c_str());
  temporary_ = pattern;

  std::FILE* messages = std::tmpfile();
  if (!messages) {
    abandon();
    throw std::runtime_error(name + ": cannot create a file for ffmpeg's messages: " + errnoText(errno));
  }
  stderrFd_ = ::dup(::fileno(messages));
  std::fclose(messages);

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    abandon();
    throw std::runtime_error(name + ": cannot make a pipe to ffmpeg: " + errnoText(errno));
  }
  pipe_ = fds[1];

  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const std::vector<std::string> args = {
      options.ffmpeg, "-hide_banner", "-loglevel", "error", "-y",
      "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-r", std::to_string(fps), "-i", "pipe:0",
      // Converted with BT.709 and tagged so: players (browsers, ffmpeg) then decode with the
      // matrix the encoder used; untagged, a BT.601 encode shifts colours by ~10 levels.
      "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv",
      "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709",
      "-c:v", "libx264", "-crf", std::to_string(options.crf), "-pix_fmt", "yuv420p",
      "-movflags", "+faststart", "-f", "mp4", temporary_.string()};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, stderrFd_, STDERR_FILENO);
  const int spawned = ::posix_spawnp(&pid_, options.ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (spawned != 0) {
    pid_ = -1;
    abandon();
    throw std::runtime_error(name + ": cannot start " + options.ffmpeg + " (" + errnoText(spawned) +
                             "); install Debian's ffmpeg package (scripts/setup.sh)");
  }
}

VideoWriter::~VideoWriter() { abandon(); }

void VideoWriter::addFrame(const ImageF& rgb) {
  if (pid_ < 0) throw std::logic_error(path_.string() + ": addFrame after finish or failure");
  if (rgb.channels != 3 || rgb.width != width_ || rgb.height != height_ ||
      rgb.pixels.size() != std::size_t(width_) * height_ * 3)
    throw std::invalid_argument(path_.string() + ": frame " + std::to_string(frames_) + " is " +
                                std::to_string(rgb.width) + "x" + std::to_string(rgb.height) + " with " +
                                std::to_string(rgb.channels) + " channels, expected " + std::to_string(width_) +
                                "x" + std::to_string(height_) + " RGB");
  for (int y = 0; y < height_; ++y) {
    const float* src = rgb.pixels.data() + std::size_t(y) * row_.size();
    for (std::size_t i = 0; i < row_.size(); ++i) row_[i] = quantize8(src[i]);
    if (const int error = writeAll(pipe_, row_.data(), row_.size()))
      fail("ffmpeg stopped reading at frame " + std::to_string(frames_) + " (" + errnoText(error) + ")");
  }
  ++frames_;
}

void VideoWriter::finish() {
  if (pid_ < 0) throw std::logic_error(path_.string() + ": finish called twice or after a failure");
  ::close(pipe_);
  pipe_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("ffmpeg failed");
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) fail("cannot move the finished video into place: " + error.message());
  temporary_.clear();
  ::close(stderrFd_);
  stderrFd_ = -1;
}

std::string VideoWriter::ffmpegMessage() const {
  if (stderrFd_ < 0) return {};
  std::string text;
  char buffer[4096];
  ssize_t n;
  off_t offset = 0;
  while ((n = ::pread(stderrFd_, buffer, sizeof buffer, offset)) > 0) {
    text.append(buffer, std::size_t(n));
    offset += n;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const auto lastLine = text.rfind('\n');
  return lastLine == std::string::npos ? text : text.substr(lastLine + 1);
}

void VideoWriter::fail(const std::string& what) {
  if (pid_ > 0) {  // let ffmpeg finish its message before reading it
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
  }
  const std::string message = ffmpegMessage();
  abandon();
  throw std::runtime_error(path_.string() + ": " + what + (message.empty() ? "" : ": " + message));
}

void VideoWriter::abandon() noexcept {
  if (pipe_ >= 0) ::close(pipe_);
  pipe_ = -1;
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  pid_ = -1;
  if (stderrFd_ >= 0) ::close(stderrFd_);
  stderrFd_ = -1;
  if (!temporary_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    temporary_.clear();
  }
}

}  // namespace testbed
