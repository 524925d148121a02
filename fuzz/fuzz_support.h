#pragma once
// What several harnesses share: stand-in techniques for the parsers that check technique
// ids and `--set` values against the registry, and a private folder for parsers that read
// files by path.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "testbed/technique/registry.h"

namespace testbed::fuzz {

// The ids the paper specs and the viewer's scripts name, each with parameters of every
// kind the parameter parser knows (bool, int, odd-only int, float, choice). Only the
// registry's entries are needed: the parsers never create a technique. Their ranges are
// the parser's concern, not the techniques', so they are not kept equal to the real ones.
inline void registerStandInTechniques() {
  auto odd = ParameterSpec::integer("kernel", 3, 1, 63, "kernel side");
  odd.oddOnly = true;
  const std::vector<ParameterSpec> specs = {
      odd,
      ParameterSpec::integer("blur", 0, 0, 32, "blur radius"),
      ParameterSpec::real("filter_width", 2.0, 0.0, 64.0, "filter width"),
      ParameterSpec::real("max_filter_radius", 8.0, 1.0, 1e6, "largest radius"),
      ParameterSpec::boolean("two_pass", false, "two passes"),
      ParameterSpec::choice("debug", "none", {"none", "discontinuity", "normals"}, "debug image"),
  };
  for (const char* id : {"sm", "pcf", "smsr", "smsr-2pass", "rsmss", "rpcf-smsr", "rpcf-rsmss", "vsm", "evsm",
                         "esm", "msm", "edtsm", "edtsm-star", "area"}) {
    if (isTechniqueRegistered(id)) continue;
    const TechniqueInfo& info = keepTechniqueInfo({.id = id, .summary = "fuzz stand-in", .parameters = specs}, "fuzz");
    addTechnique(RegisteredTechnique{&info, nullptr});
  }
}

// A folder of this process's own (libFuzzer's -jobs run several processes), made once.
inline const std::filesystem::path& scratchFolder() {
  static const std::filesystem::path folder = [] {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/testbed-fuzz-XXXXXX";
    if (!::mkdtemp(pattern.data())) std::abort();
    return std::filesystem::path(pattern);
  }();
  return folder;
}

// Writes `size` bytes to scratchFolder()/name and returns the path.
inline std::filesystem::path writeScratchFile(const std::string& name, const std::uint8_t* data,
                                              std::size_t size) {
  const auto path = scratchFolder() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                std::streamsize(size));
  return path;
}

}  // namespace testbed::fuzz
