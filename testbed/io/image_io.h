#pragma once
// Image files through OpenImageIO. Pixel rows are top-down (as files store them); GL
// readbacks are flipped by the caller. Writes go to a temporary name first and are
// renamed into place by OutputFiles, so an error never leaves a half-written file.
#include <filesystem>
#include <string>
#include <vector>

namespace testbed {

struct ImageF {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // top-down, interleaved
  float at(int x, int y, int c = 0) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

// PNG/JPEG: 8-bit with values clamped to [0,1]; EXR: float32. Throws std::runtime_error
// naming the file on failure.
void writeImage(const std::filesystem::path& file, const ImageF& image);
ImageF readImage(const std::filesystem::path& file);

// Collects the files of one command and commits them together: each write goes to
// "<name>.partial", commit() renames them all; the destructor of an uncommitted set
// removes the partial files, and the directory too if this set created it.
class OutputFiles {
 public:
  explicit OutputFiles(std::filesystem::path directory) : directory_(std::move(directory)) {}
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  void writeImage(const std::string& name, const ImageF& image);
  void writeText(const std::string& name, const std::string& text);
  void commit();
  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::filesystem::path stage(const std::string& name);
  std::filesystem::path directory_;
  std::vector<std::filesystem::path> staged_;
  bool createdDirectory_ = false;
};

}  // namespace testbed
