#include "testbed/io/image_io.h"

#include <fstream>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include "testbed/core/error.h"
#include "testbed/io/file_extension.h"
#include "testbed/io/input_file.h"

namespace testbed {
namespace {

// Encodes `image` in the format of `formatName` ("png", "openexr") into memory; `file`
// names it in messages.
std::vector<unsigned char> encodeWithFormat(const std::string& file, const ImageF& image, const std::string& formatName) {
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);  // outlives the writer, which may flush into it
  auto out = OIIO::ImageOutput::create(formatName);
  if (!out) throw std::runtime_error(file + ": no OpenImageIO writer for " + formatName);
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory))
    throw std::runtime_error(file + ": the OpenImageIO " + formatName + " writer cannot write to memory");
  const bool isFloat = formatName == "openexr";
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (isFloat && image.channels == 1) spec.channelnames = {"Y"};
  if (isFloat) spec.attribute("compression", "zip");
  if (!out->open(file, spec)) throw std::runtime_error(file + ": cannot encode: " + out->geterror());
  bool ok;
  if (isFloat) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else {
    std::vector<unsigned char> bytes(image.pixels.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = quantize8(image.pixels[i]);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  if (!ok || !out->close()) throw std::runtime_error(file + ": encoding failed: " + out->geterror());
  return encoded;
}

std::string formatFor(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  if (ext == ".exr") return "openexr";
  if (ext == ".png") return "png";
  throw std::runtime_error(file.string() + ": unsupported image extension (use .png or .exr)");
}

}  // namespace

std::vector<unsigned char> encodeImage(const std::string& name, const ImageF& image) {
  return encodeWithFormat(name, image, formatFor(name));
}

void writeImage(const std::filesystem::path& file, const ImageF& image) {
  const std::vector<unsigned char> bytes = encodeImage(file.string(), image);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out.flush()) throw std::runtime_error(file.string() + ": write failed");
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

ImageF readImage(const std::filesystem::path& file, const ImageShape& expected) {
  auto fail = [&](const std::string& what) { throw InputError(file.string() + ": " + what); };
  std::string bytes = readInputFile(file, kMaxImageFileBytes);
  // Decoded from the bytes read, so that the checks and the pixels are about one file.
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  OIIO::ImageSpec config;
  auto in = OIIO::ImageInput::open(file.string(), &config, &memory);
  if (!in) fail("not a readable image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  auto shape = [](int w, int h, int c) {
    return std::to_string(w) + "x" + std::to_string(h) + ", " + std::to_string(c) + " channel" + (c == 1 ? "" : "s");
  };
  if (spec.width != expected.width || spec.height != expected.height || spec.nchannels != expected.channels ||
      spec.depth != 1)
    fail("the image is " + shape(spec.width, spec.height, spec.nchannels) + ", expected " +
         shape(expected.width, expected.height, expected.channels));
  ImageF image{expected.width, expected.height, expected.channels, {}};
  image.pixels.resize(std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels));
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    fail("cannot read the pixels: " + in->geterror());
  return image;
}

}  // namespace testbed
