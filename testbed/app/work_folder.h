#pragma once
// A private temporary folder for what an outside program (matplotlib, ffmpeg) writes
// before the testbed stages it with the rest of a command's outputs (io/output_files.h),
// so that those files land all together or not at all. A caught signal removes it with
// its files, as it removes a staging folder (io/interrupt_cleanup.h): it holds files only.
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "testbed/io/interrupt_cleanup.h"

namespace testbed {

class WorkFolder {
 public:
  explicit WorkFolder(const std::string& prefix) {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    DeferSignals registering;  // a signal between mkdtemp and the guard would leave it behind
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
    guard_ = std::make_unique<InterruptCleanup>(pattern, InterruptCleanup::Kind::StagingFolder);
  }
  ~WorkFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  WorkFolder(const WorkFolder&) = delete;
  WorkFolder& operator=(const WorkFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

  // Writes `text` to the file `name` in the folder; a failed write (a full $TMPDIR) throws,
  // naming the file, rather than leave a truncated file for the outside program to read.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) throw std::runtime_error(file.string() + ": cannot create: " + std::strerror(errno));
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const std::string error = n < 0 ? std::strerror(errno) : "nothing written";
        ::close(fd);
        throw std::runtime_error(file.string() + ": write failed: " + error);
      }
      done += std::size_t(n);
    }
    if (::close(fd) != 0) throw std::runtime_error(file.string() + ": write failed: " + std::strerror(errno));
    return file;
  }

  // The whole of a file the outside program wrote.
  static std::string read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw std::runtime_error("cannot read " + file.string());
    return bytes.str();
  }

 private:
  std::filesystem::path path_;
  std::unique_ptr<InterruptCleanup> guard_;  // after path_: unregistered once the folder is gone
};

}  // namespace testbed
