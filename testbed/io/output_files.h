#pragma once
// The files of one command, committed together. Nothing is written outside a private
// staging folder until commit(), and a commit never replaces, or writes through, anything
// but a regular file:
//   - the constructor checks the output folder before any rendering: it creates it (and
//     its missing parents) and, inside it, a private staging folder
//     ".testbed-staging-XXXXXX" (mkdtemp, mode 0700); a bad --out is an InputError;
//   - each write creates its file in the staging folder exclusively (O_EXCL|O_NOFOLLOW);
//   - commit() refuses when a final name is held by anything but a regular file (a link,
//     a folder, a device, a FIFO), then moves the regular files of the same names into
//     the staging folder and the new ones into place, putting the old ones back if a rename
//     fails, so the set lands whole or not at all; a user's other files (sm.json.previous,
//     sm.json.partial) are never touched;
//   - an uncommitted set (an error, a signal, a crash: interrupt_cleanup.h) removes its
//     staging folder and the folders it created when they are empty.
// SIGKILL (or a crash in the middle of a commit) leaves the staging folder with the files
// written so far; its name starts with a dot and says what it is, and the outputs from
// earlier runs stay as they were.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "testbed/io/image_io.h"
#include "testbed/io/interrupt_cleanup.h"

namespace testbed {

class OutputFiles {
 public:
  // `option` names the command-line option in messages ("--out").
  explicit OutputFiles(std::filesystem::path directory, std::string option = "--out");
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Checks now that `name` can be committed: a plain file name, and nothing but a regular
  // file (or nothing) at that name in the folder. Throws InputError. Writes check it too;
  // commands claim the names they know before they render.
  void claim(const std::string& name) const;
  void writeImage(const std::string& name, const ImageF& image);  // by extension, image_io.h
  void writeText(const std::string& name, const std::string& text);
  void commit();
  const std::filesystem::path& directory() const { return directory_; }

 private:
  void writeBytes(const std::string& name, const void* data, std::size_t size);
  void removeStaging() noexcept;

  std::filesystem::path directory_, staging_;
  std::string option_;
  std::vector<std::filesystem::path> created_;  // folders this set made, outermost first
  std::vector<std::unique_ptr<InterruptCleanup>> guards_;
  std::vector<std::string> staged_;
};

}  // namespace testbed
