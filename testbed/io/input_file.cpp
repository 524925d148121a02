#include "testbed/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "testbed/core/error.h"

namespace testbed {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem) {
  throw InputError(file.string() + ": " + problem);
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// O_NONBLOCK: opening a FIFO with no writer would otherwise wait forever; fstat then
// tells what was opened, so the check and the read are about the same file.
std::uint64_t openChecked(const std::filesystem::path& file, std::uint64_t maxBytes, Descriptor& descriptor) {
  descriptor.fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (descriptor.fd < 0) {
    if (errno == ENOENT) fail(file, "no such file");
    fail(file, std::string("cannot open: ") + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(descriptor.fd, &info) != 0) fail(file, std::string("cannot stat: ") + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) fail(file, "is " + describeFileMode(info.st_mode) + ", expected a regular file");
  const auto size = std::uint64_t(info.st_size);
  if (size > maxBytes)
    fail(file, "is " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(maxBytes));
  return size;
}

}  // namespace

std::string describeFileMode(unsigned mode) {
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::uint64_t checkInputFile(const std::filesystem::path& file, std::uint64_t maxBytes) {
  Descriptor descriptor{-1};
  return openChecked(file, maxBytes, descriptor);
}

std::string readInputFile(const std::filesystem::path& file, std::uint64_t maxBytes) {
  Descriptor descriptor{-1};
  const std::uint64_t size = openChecked(file, maxBytes, descriptor);
  std::string text;
  text.reserve(size);
  char buffer[1 << 16];
  // Read to the end, not just `size` bytes: the file may still be growing; the cap holds.
  while (true) {
    const ssize_t n = ::read(descriptor.fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(file, std::string("cannot read: ") + std::strerror(errno));
    }
    if (n == 0) break;
    text.append(buffer, std::size_t(n));
    if (text.size() > maxBytes) fail(file, "grew past the limit of " + std::to_string(maxBytes) + " bytes while read");
  }
  return text;
}

}  // namespace testbed
