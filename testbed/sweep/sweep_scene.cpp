#include "testbed/sweep/sweep_scene.h"

#include <nlohmann/json.hpp>

#include "testbed/io/json_input.h"

namespace testbed {

Scene loadSweepScene(const std::filesystem::path& file, std::optional<int> subdivide) {
  if (!subdivide) return loadScene(file);
  // The strict reader scenes get (loadScene): caps, regular files only, duplicate keys refused.
  nlohmann::json document = readJsonInput(file);
  if (document.is_object() && document.contains("objects") && document["objects"].is_array())
    for (auto& object : document["objects"])
      if (object.is_object() && object.contains("mesh")) object["subdivide"] = *subdivide;
  return parseScene(document, file);
}

}  // namespace testbed
