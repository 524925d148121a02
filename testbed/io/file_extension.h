#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace testbed {

// A file's extension in lower case (".PNG" -> ".png"): formats are chosen by extension, and
// users name files both ways.
inline std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace testbed
