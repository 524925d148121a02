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

// A [0,1] value as an 8-bit channel the way PNGs are written (NaN → 0, clamped, rounded),
// so a viewer's window shows exactly the bytes of the file.
inline unsigned char quantize8(float v) {
  const float clamped = v != v ? 0.0f : (v < 0 ? 0.0f : (v > 1 ? 1.0f : v));
  return static_cast<unsigned char>(clamped * 255.0f + 0.5f);
}

// PNG/JPEG: 8-bit with values clamped to [0,1] (quantize8); EXR: float32. Throws std::runtime_error
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
