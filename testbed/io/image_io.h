#pragma once
// Image files through OpenImageIO. Pixel rows are top-down (as files store them); GL
// readbacks are flipped by the caller. Commands write their images through OutputFiles
// (output_files.h), which stages and commits them; encodeImage gives it the bytes.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace testbed {

// The font figure labels are drawn in (Debian's fonts-dejavu-core, which setup.sh installs).
inline constexpr const char* kLabelFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

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
// The file's bytes in memory, the format chosen by `name`'s extension (.png or .exr).
std::vector<unsigned char> encodeImage(const std::string& name, const ImageF& image);
ImageF readImage(const std::filesystem::path& file);

// What a file must hold to be read by the checked readImage.
struct ImageShape {
  int width = 0, height = 0, channels = 0;
};
inline constexpr std::uint64_t kMaxImageFileBytes = 2ull << 30;
// For images from elsewhere (a shard's figure cells): read through input_file.h (a regular
// file, at most kMaxImageFileBytes) and decoded only when its header declares exactly
// `expected`, so a small file cannot ask for gigabytes or a mismatched one be read out of
// bounds. Throws InputError "<file>: <problem>".
ImageF readImage(const std::filesystem::path& file, const ImageShape& expected);

}  // namespace testbed

// OutputFiles lived here once; code that includes this header for it still finds it.
#include "testbed/io/output_files.h"  // IWYU pragma: export
