// Sweep specs and shards as a careless or hostile user hands them in (docs/input-limits.md):
// every file through the strict capped reader, every refusal one line and exit 2 before
// anything renders or is written; merge verifies what it merges and never writes over
// its inputs.
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json tinySpec() {
  json spec = json::parse(readFile(tinySpecFile()));
  spec["scenes"]["wall"] = (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string();
  return spec;
}

struct Case {
  std::string name;  // also the spec's file name
  std::string text;  // the file's contents
  std::string expected;
};

// PNG chunks carry a CRC-32 (ISO 3309) of their type and data.
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string bigEndian(std::uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG of a few dozen bytes whose header asks for width × height RGB pixels.
std::string pngHeaderOnly(std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = "IHDR" + bigEndian(width) + bigEndian(height) + std::string{8, 2, 0, 0, 0};
  const std::string idat = std::string("IDAT") + "\x78\x9c";  // the start of a zlib stream: pixels follow "later"
  return std::string("\x89PNG\r\n\x1a\n", 8) + bigEndian(13) + ihdr + bigEndian(crc32(ihdr)) + bigEndian(2) + idat +
         bigEndian(crc32(idat)) + bigEndian(0) + "IEND" + bigEndian(crc32("IEND"));
}

TEST(HostileSweep, SpecsAreReadStrictlyAndCappedBeforeAnythingRenders) {
  TempDir tmp("hostile-spec");
  auto spec = [](auto&& change) {
    json s = tinySpec();
    change(s);
    return s.dump();
  };
  std::string deep = R"({"name": "tiny", "comment": )";
  deep += std::string(70000, '[') + std::string(70000, ']') + "}";
  std::string hugeNumber = tinySpec().dump();
  hugeNumber.replace(hugeNumber.find("[1.0,"), 4, "[1e999");  // rows[0].paper[0]
  writeFile(tmp / "dup-scene.json", R"({"name": "dup", "name": "again", "objects": []})");
  const std::vector<Case> cases = {
      {"deep.json", deep, "deep.json: JSON nested deeper than 64 levels"},
      {"huge-number.json", hugeNumber, "huge-number.json: rows[0].paper[0]: not a finite number"},
      {"twice.json", R"({"name": "tiny", "name": "tiny"})", "twice.json: name: key given twice in one object"},
      {"long-name.json", spec([](json& s) { s["name"] = std::string(300, 'n'); }),
       "long-name.json: name: 300 characters, more than the limit of 64"},
      {"scene-id.json", spec([](json& s) { s["scenes"]["../up"] = s["scenes"]["wall"]; }),
       "scene-id.json: scenes[\"../up\"]: expected lower-case letters"},
      {"passes.json", spec([](json& s) { s["rows"][1]["passes"] = {"visibility", "visibility"}; }),
       "passes.json: rows[1].passes[1]: \"visibility\" is already in the list"},
      {"columns.json", spec([](json& s) { s["columns"] = json(std::vector<json>(257, {{"label", "c"}})); }),
       "columns.json: columns: 257 columns, more than the limit of 256"},
      {"cells.json", spec([](json& s) { s["rows"][0]["techniques"] = std::vector<std::string>(10001, "sm"); }),
       "cells.json: rows[0].techniques: the table reaches 20002 cells here, more than the limit of 20000"},
      {"big.json", spec([](json& s) { s["comment"] = std::string(1 << 20, 'x'); }), "bytes, more than the limit of 1048576"},  // the size holds the checkout's path
      {"subdivided.json", spec([&](json& s) {
         s["scenes"]["wall"] = (tmp / "dup-scene.json").string();
         s["settings"]["subdivide"] = 1;
       }),
       "dup-scene.json: name: key given twice in one object"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    writeFile(tmp / c.name, c.text);
    const RunResult run = runTestbed({"sweep", "--spec", (tmp / c.name).string(), "--out", (tmp / "out").string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.describe();
    EXPECT_EQ(run.err.find("[1/"), std::string::npos) << "nothing renders: " << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
  }
  // Not regular files: refused at once, naming the file, without reading or blocking.
  ASSERT_EQ(::mkfifo((tmp / "fifo.json").c_str(), 0600), 0);
  for (const auto& [file, kind] : std::vector<std::pair<fs::path, std::string>>{
           {tmp / "fifo.json", "a FIFO"}, {"/dev/zero", "a device"}, {tmp.path(), "a folder"}}) {
    SCOPED_TRACE(file.string());
    // The default timeout only guards against a run that blocks; a refusal returns at once.
    const RunResult run = runTestbed({"sweep", "--spec", file.string(), "--out", (tmp / "out").string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(file.string() + ": is " + kind + ", expected a regular file"), std::string::npos)
        << run.describe();
  }
}

class HostileMerge : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new TempDir("hostile-merge");
    for (const char* shard : {"1/2", "2/2"}) {
      const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--shard", shard, "--out",
                                        (*tmp_ / ("shard" + std::string(1, shard[0]))).string()});
      ASSERT_EQ(run.exitCode, 0) << run.describe();
    }
  }
  static void TearDownTestSuite() { delete tmp_; }

  // A copy of shard 2 with `file` replaced by `text`.
  static fs::path shard2With(const std::string& name, const std::string& file, const std::string& text) {
    const fs::path copy = *tmp_ / name;
    fs::copy(*tmp_ / "shard2", copy, fs::copy_options::recursive);
    fs::remove(copy / file);
    writeFile(copy / file, text);
    return copy;
  }
  static json shard2Json(const std::string& file) { return json::parse(readFile(*tmp_ / "shard2" / file)); }

  static RunResult merge(const fs::path& out, const fs::path& second) {
    return runTestbed({"merge", "--no-plot", "--out", out.string(), (*tmp_ / "shard1").string(), second.string()},
                      {.timeoutSeconds = 60});
  }

  static TempDir* tmp_;
};

TempDir* HostileMerge::tmp_ = nullptr;

// What an interrupted run left in --out/.testbed-resume is read like any file from
// elsewhere: garbage, another cell's record, a folder or a link in a cell's name are
// named on a line each and their cells run again; the run ends with every record.
TEST(HostileSweep, ResumeFilesAreVerifiedNotTrusted) {
  TempDir tmp("hostile-resume");
  const std::string spec = tinySpecFile().string();
  ASSERT_EQ(runTestbed({"sweep", "--spec", spec, "--no-plot", "--out", (tmp / "whole").string()}).exitCode, 0);
  const json manifest = json::parse(readFile(tmp / "whole" / "sweep.json"));
  const json records = json::parse(readFile(tmp / "whole" / "records.json"));
  const fs::path resume = tmp / "out" / ".testbed-resume";
  fs::create_directories(resume / "cell-3.json");  // a folder
  writeFile(resume / "cell-0.json", "not json {");
  writeFile(resume / "cell-1.json", std::string(70000, '[') + std::string(70000, ']'));
  const json entry = {{"spec_fingerprint", manifest["spec_fingerprint"]}, {"build", manifest["build"]}, {"record", records[4]}};
  writeFile(resume / "cell-2.json", entry.dump());  // cell 4's record under cell 2's name
  fs::create_symlink(tmp / "whole" / "records.json", resume / "cell-4.json");
  json otherBuild = entry;
  otherBuild["build"] = "0000000000000000";
  writeFile(resume / "cell-99.json", otherBuild.dump());
  const RunResult run = runTestbed({"sweep", "--spec", spec, "--no-plot", "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_EQ(run.err.find("sweep: resuming"), std::string::npos) << run.err;  // nothing was kept
  for (const char* expected : {"cell-0.json: line 1", "cell-1.json: JSON nested deeper than 64 levels",
                               "cell-2.json: record: its cell is not 2", "cell-3.json: not a regular file",
                               "cell-4.json: not a regular file", "cell-99.json: of another spec or build"})
    EXPECT_NE(run.err.find(expected), std::string::npos) << expected << "\n" << run.err;
  EXPECT_EQ(cellsOf(json::parse(readFile(tmp / "out" / "records.json"))), cellsOf(records));
  EXPECT_TRUE(fs::is_directory(resume / "cell-3.json"));  // not ours to remove
}

TEST_F(HostileMerge, WhatIsMergedIsVerifiedAndNothingIsWritten) {
  json spec = shard2Json("spec.json"), records = shard2Json("records.json"), manifest = shard2Json("sweep.json");
  json editedSpec = spec;
  editedSpec["rows"][0]["paper"][0] = 99.0;
  json otherTechnique = records, otherParams = records;
  otherTechnique[0]["technique"] = otherTechnique[0]["technique"] == "sm" ? "pcf" : "sm";
  otherParams[0]["params"]["kernel"] = 5;  // a parameter its cell does not have
  json otherPath = records;  // as if shard 2 ran with the other --path
  for (auto& record : otherPath) record["path"] = record["path"] == "paper" ? "fast" : "paper";
  json otherShaderPath = records;  // as if shard 2 ran with TESTBED_SHADER_PATH=spirv
  for (auto& record : otherShaderPath) record["shader_path"] = "spirv";
  json badOverrides = manifest;
  badOverrides["overrides"] = {{"shadow_map", "big"}};
  std::string huge = records.dump();
  huge.replace(huge.find("\"cell\":") + 7, 1, "1e999");  // the first record's cell index
  struct FileCase {
    std::string name, file, text, expected;
  };
  const std::vector<FileCase> cases = {
      {"edited-spec", "spec.json", editedSpec.dump(), "edited-spec/spec.json: does not match the shard's spec_fingerprint"},
      {"other-technique", "records.json", otherTechnique.dump(), "other-technique/records.json: [0].technique: "},
      {"other-params", "records.json", otherParams.dump(), ".params: "},
      {"other-path", "records.json", otherPath.dump(), "other-path/records.json: [0].path: made on the "},
      {"other-shader-path", "records.json", otherShaderPath.dump(),
       "other-shader-path/records.json: [0].shader_path: compiled by spirv, "},
      {"bad-overrides", "sweep.json", badOverrides.dump(), "bad-overrides/sweep.json: overrides.shadow_map: expected an integer"},
      {"huge-number", "records.json", huge, "huge-number/records.json: [0].cell: not a finite number"},
      {"deep", "spec.json", std::string(70000, '[') + std::string(70000, ']'), "deep/spec.json: JSON nested deeper than 64 levels"},
  };
  for (const FileCase& c : cases) {
    SCOPED_TRACE(c.name);
    const RunResult run = merge(*tmp_ / "out", shard2With(c.name, c.file, c.text));
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(*tmp_ / "out")) << run.describe();
  }
}

// Figure images are decoded only at their cell's size and channels: a small PNG cannot
// ask for 10 GB, a mismatched one cannot be read out of bounds.
TEST_F(HostileMerge, FigureImagesAreCheckedFromTheirHeader) {
  const fs::path huge = shard2With("huge-png", "figure-cell-1.png", pngHeaderOnly(60000, 60000));
  ImageF small{8, 8, 3, std::vector<float>(8 * 8 * 3, 0.5f)};
  const std::vector<unsigned char> bytes = encodeImage("x.png", small);
  const fs::path wrong = shard2With("small-png", "figure-cell-1.png", std::string(bytes.begin(), bytes.end()));
  for (const auto& [shard, expected] : std::vector<std::pair<fs::path, std::string>>{
           {huge, "huge-png/figure-cell-1.png: the image is 60000x60000, 3 channels, expected 160x90, 3 channels"},
           {wrong, "small-png/figure-cell-1.png: the image is 8x8, 3 channels, expected 160x90"}}) {
    const RunResult run = merge(*tmp_ / "out", shard);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(*tmp_ / "out")) << run.describe();
  }
}

TEST_F(HostileMerge, NeverWritesOverItsInputsOrReadsWhatIsNotAFile) {
  const std::string before = readFile(*tmp_ / "shard1" / "records.json");
  for (const fs::path& out : {*tmp_ / "shard1", *tmp_ / "shard1" / "inside"}) {
    const RunResult run = merge(out, *tmp_ / "shard2");
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find("merge never writes over its inputs"), std::string::npos) << run.describe();
  }
  EXPECT_TRUE(fileHolds(*tmp_ / "shard1" / "records.json", before));
  EXPECT_FALSE(fs::exists(*tmp_ / "shard1" / "inside"));

  const fs::path fifo = *tmp_ / "fifo-shard";
  fs::copy(*tmp_ / "shard2", fifo, fs::copy_options::recursive);
  fs::remove(fifo / "records.json");
  ASSERT_EQ(::mkfifo((fifo / "records.json").c_str(), 0600), 0);
  const fs::path folder = shard2With("folder-shard", "sweep.json", "");
  fs::remove(folder / "sweep.json");
  fs::create_directory(folder / "sweep.json");
  for (const auto& [shard, expected] : std::vector<std::pair<fs::path, std::string>>{
           {fifo, "fifo-shard/records.json: is a FIFO"}, {folder, "folder-shard/sweep.json: is a folder"}}) {
    const RunResult run = merge(*tmp_ / "out", shard);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.describe();
  }
}

}  // namespace
}  // namespace testbed::test
