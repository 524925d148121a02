#include "testbed/harness/record.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "testbed/core/error.h"
#include "testbed/harness/metric_table.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every metrics.json and records.json committed under `folder`.
std::vector<fs::path> recordFiles(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().filename() == "metrics.json" || entry.path().filename() == "records.json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// "" when equal; else the first line that differs, with its number, in both texts.
std::string firstDifference(const std::string& written, const std::string& committed) {
  std::istringstream a(written), b(committed);
  std::string lineA, lineB;
  for (std::size_t n = 1;; ++n) {
    const bool moreA = bool(std::getline(a, lineA)), moreB = bool(std::getline(b, lineB));
    if (!moreA && !moreB) return "";
    if (!moreA || !moreB || lineA != lineB)
      return "line " + std::to_string(n) + ": written \"" + (moreA ? lineA : "<end>") + "\", committed \"" +
             (moreB ? lineB : "<end>") + "\"";
  }
}

// The files of today read into typed records and written again are the same bytes: same
// keys, same order, same number formatting.
TEST(Record, CommittedRecordsRoundTripByteForByte) {
  std::size_t records = 0;
  for (const char* folder : {"tests/baselines", "results"}) {
    const auto files = recordFiles(fs::path(TESTBED_SOURCE_DIR) / folder);
    ASSERT_FALSE(files.empty()) << folder;
    for (const auto& file : files) {
      SCOPED_TRACE(file.string());
      const std::string text = readText(file);
      const json parsed = json::parse(text);
      json written = json::array();
      for (std::size_t i = 0; i < parsed.size(); ++i) {
        written.push_back(readRecord(parsed[i], "[" + std::to_string(i) + "]"));
        // A sweep's row and column labels come from its spec, not from the record
        // (sweep/sweep_records.cpp); they are carried over as written.
        for (const char* label : {"row", "column", "entries"})
          if (parsed[i].contains(label)) written.back()[label] = parsed[i][label];
        // Records written before records carried their derived figures lack the block
        // (docs/record.md "The record": `derived`); the writer adds it from the stored figures.
        if (!parsed[i].contains("derived")) written.back().erase("derived");
      }
      // Compared line by line: a failure names the first differing line rather than asking
      // GoogleTest to diff two files of megabytes.
      EXPECT_EQ(firstDifference(written.dump(2) + "\n", text), "");
      records += written.size();
    }
  }
  EXPECT_GT(records, 100u);
}

json baselineRecord(const std::string& technique) {
  const json all = json::parse(readText(fs::path(TESTBED_SOURCE_DIR) / "tests/baselines/fence/metrics.json"));
  for (const auto& r : all)
    if (r["technique"] == technique) return json(r.get<Record>());  // as the writer writes it today
  throw std::runtime_error("no " + technique + " in tests/baselines/fence");
}

TEST(Record, TypedFieldsHoldTheFile) {
  const json j = baselineRecord("pcf");
  const Record r = j.get<Record>();
  EXPECT_EQ(r.technique, "pcf");
  EXPECT_EQ(r.width, j["size"][0].get<int>());
  EXPECT_EQ(r.timing == TimingSource::Wall ? "wall" : "gpu", j["timing"].get<std::string>());
  EXPECT_EQ(frameTimeMs(r), j[r.timing == TimingSource::Wall ? "wall_ms" : "gpu_ms"]["total"].get<double>());
  EXPECT_EQ(r.memoryBytes, j["memory_bytes"].get<std::uint64_t>());
  ASSERT_TRUE(r.error.has_value());
  EXPECT_EQ(r.error->boundaryMean, j["error"]["boundary_px"]["mean"].get<double>());
  EXPECT_FALSE(r.error->softRmse.has_value());  // null in the file
  EXPECT_EQ(r.light.offsetWorld.has_value(), j["light"].contains("offset_world"));
  EXPECT_EQ(r.params, j["params"]);
}

TEST(Record, ErrorBlockHasExactlyTheContractKeys) {
  Record r = baselineRecord("sm").get<Record>();
  r.error = ErrorMetrics{};
  r.error->boundaryMean = 2.5;
  json j = r;
  std::set<std::string> keys, boundaryKeys;
  for (const auto& item : j.at("error").items()) keys.insert(item.key());
  EXPECT_EQ(keys, (std::set<std::string>{"mismatch_pct", "edge_mismatch_pct", "rmse", "leak_pct", "overestimation_pct",
                                         "boundary_px", "soft_rmse"}));
  for (const auto& item : j.at("error").at("boundary_px").items()) boundaryKeys.insert(item.key());
  EXPECT_EQ(boundaryKeys, (std::set<std::string>{"mean", "p95"}));
  EXPECT_EQ(j["error"]["boundary_px"]["mean"].get<double>(), 2.5);
  EXPECT_TRUE(j["error"]["soft_rmse"].is_null());
  r.error->softRmse = 0.25;
  EXPECT_EQ(json(r)["error"]["soft_rmse"].get<double>(), 0.25);
  // Against the area-light reference too: the penumbra metrics, and each metric's reference.
  r.error->softPenumbraMae = 0.125;
  r.error->softOutsideMae = 0.0625;
  r.error->softUmbraLeak = 0.5;
  const json soft = r;
  keys.clear();
  for (const auto& item : soft.at("error").items()) keys.insert(item.key());
  EXPECT_EQ(keys, (std::set<std::string>{"mismatch_pct", "edge_mismatch_pct", "rmse", "leak_pct", "overestimation_pct",
                                         "boundary_px", "soft_rmse", "soft_penumbra_mae", "soft_outside_mae",
                                         "soft_umbra_leak", "reference"}));
  EXPECT_EQ(soft["error"]["reference"]["rmse"], "hard");
  EXPECT_EQ(soft["error"]["reference"]["soft_umbra_leak"], "soft");
  EXPECT_EQ(soft.get<Record>().error->softUmbraLeak, 0.5);
  EXPECT_EQ(json(soft.get<Record>()), soft);
  r.error.reset();
  EXPECT_TRUE(json(r)["error"].is_null());
  EXPECT_FALSE(json(r).get<Record>().error.has_value());
}

// The work block: counts per pass and their sums; null where the GL has no pipeline
// statistics (never zeros); no key at all in records made before the counters.
TEST(Record, WorkBlockIsCountsNullOrAbsent) {
  const json j = baselineRecord("sm");
  Record r = j.get<Record>();
  ASSERT_TRUE(r.work) << "tests/baselines carry work counts (scripts/baselines.sh)";
  EXPECT_EQ(r.work->passes.size(), j["gpu_ms"]["passes"].size());
  WorkCounts sum{};
  for (const auto& [name, counts] : r.work->passes) sum += counts;
  EXPECT_EQ(r.work->total, sum);
  EXPECT_EQ(r.work->total[1], j["work"]["total"]["fragment_invocations"].get<std::uint64_t>());

  r.work.reset();
  const json uncounted = r;
  EXPECT_TRUE(uncounted.at("work").is_null());
  const Record back = uncounted.get<Record>();
  EXPECT_FALSE(back.work);
  EXPECT_TRUE(back.workRecorded);

  json old = j;
  old.erase("work");
  const Record before = old.get<Record>();
  EXPECT_FALSE(before.work);
  EXPECT_FALSE(before.workRecorded);
  EXPECT_FALSE(json(before).contains("work"));
}

// The shader compiler a record names comes back as written; a record written before it
// was named reads as the driver's GLSL compiler's and is written again without the key.
TEST(Record, ShaderPathRoundTripsAndDefaultsToGlsl) {
  json j = baselineRecord("sm");
  j["shader_path"] = "spirv";
  const Record spirv = j.get<Record>();
  ASSERT_TRUE(spirv.shaderPath);
  EXPECT_EQ(*spirv.shaderPath, ShaderPath::Spirv);
  EXPECT_EQ(compiledBy(spirv), ShaderPath::Spirv);
  EXPECT_EQ(json(spirv), j);
  j["shader_path"] = "glsl";
  EXPECT_EQ(compiledBy(j.get<Record>()), ShaderPath::Glsl);
  EXPECT_EQ(json(j.get<Record>()), j);

  j.erase("shader_path");
  const Record old = j.get<Record>();
  EXPECT_FALSE(old.shaderPath);
  EXPECT_EQ(compiledBy(old), ShaderPath::Glsl);
  EXPECT_FALSE(json(old).contains("shader_path"));

  j["shader_path"] = "hlsl";
  EXPECT_EQ(test::inputErrorOf([&] { readRecord(j, "runs/x.json: [0]"); }).value_or("accepted"),
            "runs/x.json: [0].shader_path: expected \"glsl\" or \"spirv\"");
  j["shader_path"] = 1;
  EXPECT_EQ(test::inputErrorOf([&] { readRecord(j, "runs/x.json: [0]"); }).value_or("accepted"),
            "runs/x.json: [0].shader_path: expected a string, got 1");
}

// The checked JSON reader's rule (io/json_reader.h), as in scene files and sweep specs.
TEST(Record, WholeNumbersMayBeWrittenAsFloats) {
  json j = baselineRecord("pcf");
  const std::uint64_t triangles = j["triangles"].get<std::uint64_t>();
  j["triangles"] = double(triangles);
  EXPECT_EQ(readRecord(j, "runs/x.json: [0]").triangles, triangles);
}

TEST(Record, MalformedRecordsNameTheField) {
  auto message = [](const json& j) {
    return test::inputErrorOf([&] { readRecord(j, "runs/x.json: [4]"); }).value_or("accepted");
  };
  const json good = baselineRecord("pcf");
  EXPECT_NO_THROW(readRecord(good, "runs/x.json: [4]"));
  json r = good;
  r.erase("scene");
  EXPECT_EQ(message(r), "runs/x.json: [4].scene: missing required key");
  r = good;
  r["gpu_ms"]["passes"]["shadow-map"] = "slow";
  EXPECT_EQ(message(r), "runs/x.json: [4].gpu_ms.passes.shadow-map: expected a number, got \"slow\"");
  r = good;
  r["error"]["boundary_px"]["p95"] = nullptr;  // how a NaN is written
  EXPECT_EQ(message(r), "runs/x.json: [4].error.boundary_px.p95: expected a number, got null");
  r = good;
  r["cpu_ms"] = -2.0;
  EXPECT_EQ(message(r), "runs/x.json: [4].cpu_ms: expected a non-negative number, got -2");
  r = good;
  r["light"]["eye"] = {1.0, 2.0};
  EXPECT_EQ(message(r), "runs/x.json: [4].light.eye: expected an array of 3 numbers, got [1.0,2.0]");
  r = good;
  r["size"] = {160};
  EXPECT_EQ(message(r), "runs/x.json: [4].size: expected [width, height], got [160]");
  r = good;
  r["triangles"] = 1.5;
  EXPECT_EQ(message(r), "runs/x.json: [4].triangles: expected a non-negative integer, got 1.5");
  EXPECT_EQ(message(json::array()), "runs/x.json: [4]: expected an object (a record)");
  // from_json (j.get<Record>()) says the same without the file.
  r = good;
  r["error"].erase("rmse");
  try {
    (void)r.get<Record>();
    ADD_FAILURE() << "accepted a record without error.rmse";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "error.rmse: missing required key");
  }
}

}  // namespace
}  // namespace testbed
