#include "testbed/sweep/sweep_scene.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"

namespace testbed {

Scene loadSweepScene(const std::filesystem::path& file, std::optional<int> subdivide) {
  if (!subdivide) return loadScene(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the scene file");
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(file.string() + ": not valid JSON (" + std::string(error.what()) + ")");
  }
  if (document.is_object() && document.contains("objects") && document["objects"].is_array())
    for (auto& object : document["objects"])
      if (object.is_object() && object.contains("mesh")) object["subdivide"] = *subdivide;
  return parseScene(document, file);
}

}  // namespace testbed
