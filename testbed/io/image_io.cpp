#include "testbed/io/image_io.h"

#include <fstream>
#include <stdexcept>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

namespace testbed {


namespace {

std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Writes `image` to `file` in the format of `formatName` ("png", "openexr").
void writeWithFormat(const std::filesystem::path& file, const ImageF& image, const std::string& formatName) {
  auto out = OIIO::ImageOutput::create(formatName);
  if (!out) throw std::runtime_error(file.string() + ": no OpenImageIO writer for " + formatName);
  const bool isFloat = formatName == "openexr";
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (isFloat && image.channels == 1) spec.channelnames = {"Y"};
  if (isFloat) spec.attribute("compression", "zip");
  if (!out->open(file.string(), spec))
    throw std::runtime_error(file.string() + ": cannot write: " + out->geterror());
  bool ok;
  if (isFloat) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else {
    std::vector<unsigned char> bytes(image.pixels.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = quantize8(image.pixels[i]);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  if (!ok || !out->close()) throw std::runtime_error(file.string() + ": write failed: " + out->geterror());
}

std::string formatFor(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  if (ext == ".exr") return "openexr";
  if (ext == ".png") return "png";
  throw std::runtime_error(file.string() + ": unsupported image extension (use .png or .exr)");
}

}  // namespace

void writeImage(const std::filesystem::path& file, const ImageF& image) {
  writeWithFormat(file, image, formatFor(file));
}

ImageF readImage(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(file.string() + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  ImageF image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error(file.string() + ": read failed: " + in->geterror());
  return image;
}

OutputFiles::~OutputFiles() {
  std::error_code ignored;
  for (const auto& partial : staged_) std::filesystem::remove(partial, ignored);
  if (createdDirectory_ && std::filesystem::is_empty(directory_, ignored)) std::filesystem::remove(directory_, ignored);
}

std::filesystem::path OutputFiles::stage(const std::string& name) {
  if (!std::filesystem::exists(directory_)) createdDirectory_ = std::filesystem::create_directories(directory_);
  auto partial = directory_ / (name + ".partial");
  staged_.push_back(partial);
  return partial;
}

void OutputFiles::writeImage(const std::string& name, const ImageF& image) {
  const auto partial = stage(name);
  writeWithFormat(partial, image, formatFor(name));
}

void OutputFiles::writeText(const std::string& name, const std::string& text) {
  const auto partial = stage(name);
  std::ofstream out(partial, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error((directory_ / name).string() + ": write failed");
}

void OutputFiles::commit() {
  // Two phases so the set lands whole or not at all: earlier files of the same names are
  // moved aside first, and put back if any rename fails.
  namespace fs = std::filesystem;
  std::vector<std::pair<fs::path, fs::path>> movedAside, placed;  // (from, to)
  auto finalOf = [](fs::path partial) { return partial.replace_extension(); };
  for (const auto& partial : staged_)
    if (fs::is_directory(finalOf(partial)))
      throw std::runtime_error(finalOf(partial).string() + ": a folder is in the way of the output file");
  try {
    for (const auto& partial : staged_) {
      const fs::path final = finalOf(partial);
      if (fs::exists(fs::symlink_status(final))) {
        fs::path aside = final;
        aside += ".previous";
        fs::rename(final, aside);
        movedAside.emplace_back(aside, final);
      }
    }
    for (const auto& partial : staged_) {
      fs::rename(partial, finalOf(partial));
      placed.emplace_back(partial, finalOf(partial));
    }
  } catch (...) {
    std::error_code ignored;
    for (const auto& [partial, final] : placed) fs::rename(final, partial, ignored);
    for (const auto& [aside, final] : movedAside) fs::rename(aside, final, ignored);
    throw;
  }
  std::error_code ignored;
  for (const auto& [aside, final] : movedAside) fs::remove(aside, ignored);
  staged_.clear();
  createdDirectory_ = false;
}

}  // namespace testbed
