#include "testbed/io/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "testbed/core/error.h"
#include "testbed/io/input_file.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

std::string lastError() { return std::strerror(errno); }

// True when nothing is at `file` or a regular file is (the only things a commit replaces);
// else `kind` says what is there.
bool replaceable(const fs::path& file, std::string& kind) {
  struct stat info {};
  if (::lstat(file.c_str(), &info) != 0) {
    if (errno == ENOENT) return true;
    kind = "not accessible (" + lastError() + ")";
    return false;
  }
  if (S_ISREG(info.st_mode)) return true;
  kind = S_ISLNK(info.st_mode) ? "a symbolic link" : describeFileMode(info.st_mode);
  return false;
}

}  // namespace

OutputFiles::OutputFiles(fs::path directory, std::string option)
    : directory_(std::move(directory)), option_(std::move(option)) {
  const std::string where = option_ + " " + directory_.string();
  if (directory_.empty()) throw InputError(option_ + ": the path is empty");
  try {
    // Missing folders are made one level at a time, so that exactly ours are known.
    fs::path prefix;
    for (const auto& part : directory_) {
      if (part.empty()) continue;  // a trailing '/'
      prefix /= part;
      if (part.string().size() > NAME_MAX) throw InputError(where + ": a name in it is longer than " +
                                                            std::to_string(NAME_MAX) + " bytes");
      struct stat info {};
      if (::stat(prefix.c_str(), &info) == 0) {
        if (!S_ISDIR(info.st_mode)) throw InputError(where + ": " + prefix.string() + " is not a folder");
        continue;
      }
      if (errno != ENOENT) throw InputError(where + ": " + prefix.string() + ": " + lastError());
      DeferSignals registering;  // a signal between mkdir and the guard would leave it behind
      if (::mkdir(prefix.c_str(), 0777) != 0) {
        // Shards started together share parents (OUT/shards/K-of-N): a folder another
        // process made meanwhile is success, as with mkdir -p; it is not ours to remove.
        if (errno == EEXIST && ::stat(prefix.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) continue;
        throw InputError(where + ": cannot create the folder " + prefix.string() + ": " + lastError());
      }
      created_.push_back(prefix);
      guards_.push_back(std::make_unique<InterruptCleanup>(prefix.string(), InterruptCleanup::Kind::CreatedFolder));
    }
    std::string pattern = (directory_ / ".testbed-staging-XXXXXX").string();
    DeferSignals registering;
    if (!::mkdtemp(pattern.data())) throw InputError(where + ": cannot write in the folder: " + lastError());
    staging_ = pattern;
    guards_.push_back(std::make_unique<InterruptCleanup>(pattern, InterruptCleanup::Kind::StagingFolder));
  } catch (...) {
    removeStaging();
    throw;
  }
}

OutputFiles::~OutputFiles() { removeStaging(); }

void OutputFiles::removeStaging() noexcept {
  if (!staging_.empty()) {
    for (const auto& name : staged_) ::unlink((staging_ / name).c_str());
    ::rmdir((staging_ / "previous").c_str());
    ::rmdir(staging_.c_str());
  }
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) ::rmdir(it->c_str());  // only if empty
  staged_.clear();
  created_.clear();
  staging_.clear();
  guards_.clear();
}

void OutputFiles::claim(const std::string& name) const {
  const fs::path file = directory_ / name;
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
    throw InputError(option_ + " " + file.string() + ": not a file name");
  if (name.size() > NAME_MAX)
    throw InputError(option_ + " " + file.string() + ": the file name is longer than " + std::to_string(NAME_MAX) +
                     " bytes");
  std::string kind;
  if (!replaceable(file, kind))
    throw InputError(option_ + " " + file.string() + ": is " + kind + "; only a regular file is replaced");
}

void OutputFiles::writeBytes(const std::string& name, const void* data, std::size_t size) {
  claim(name);
  const fs::path file = staging_ / name;
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error((directory_ / name).string() + ": cannot create: " + lastError());
  staged_.push_back(name);
  const char* bytes = static_cast<const char*>(data);
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string error = lastError();
      ::close(fd);
      throw std::runtime_error((directory_ / name).string() + ": write failed: " + error);
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) throw std::runtime_error((directory_ / name).string() + ": write failed: " + lastError());
}

void OutputFiles::writeImage(const std::string& name, const ImageF& image) {
  const std::vector<unsigned char> bytes = encodeImage(name, image);
  writeBytes(name, bytes.data(), bytes.size());
}

void OutputFiles::writeText(const std::string& name, const std::string& text) {
  writeBytes(name, text.data(), text.size());
}

void OutputFiles::commit() {
  DeferSignals committing;  // files move in and out of the staging folder below
  for (const auto& name : staged_) claim(name);
  const fs::path previous = staging_ / "previous";
  std::vector<std::string> movedAside, placed;
  auto fail = [](const fs::path& file, const std::string& what) {
    throw std::runtime_error(file.string() + ": " + what + ": " + lastError());
  };
  try {
    for (const auto& name : staged_) {
      const fs::path final = directory_ / name;
      struct stat info {};
      if (::lstat(final.c_str(), &info) != 0 && errno == ENOENT) continue;
      if (movedAside.empty() && ::mkdir(previous.c_str(), 0700) != 0) fail(previous, "cannot create");
      if (::rename(final.c_str(), (previous / name).c_str()) != 0) fail(final, "cannot move aside");
      movedAside.push_back(name);
      // Swapped for something else since claim()? Then it goes back and nothing is replaced.
      std::string kind;
      if (!replaceable(previous / name, kind))
        throw InputError(option_ + " " + final.string() + ": became " + kind + " while writing; not replacing it");
    }
    for (const auto& name : staged_) {
      const fs::path final = directory_ / name;
      if (::rename((staging_ / name).c_str(), final.c_str()) != 0) fail(final, "cannot put in place");
      placed.push_back(name);
    }
  } catch (...) {
    for (const auto& name : placed) ::rename((directory_ / name).c_str(), (staging_ / name).c_str());
    for (const auto& name : movedAside) ::rename((previous / name).c_str(), (directory_ / name).c_str());
    throw;
  }
  for (const auto& name : movedAside) ::unlink((previous / name).c_str());
  staged_.clear();
  created_.clear();  // the folders now hold the outputs: they stay
  removeStaging();
}

}  // namespace testbed
