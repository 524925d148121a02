// Sweep specs, cells, shards and tables without a GL context: validation messages, the
// shard partition, the paper specs' shapes and the table arithmetic.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/sweep/sweep_plan.h"
#include "testbed/sweep/sweep_passes.h"
#include "testbed/sweep/sweep_records.h"
#include "testbed/sweep/sweep_spec.h"
#include "testbed/sweep/sweep_table.h"
#include "testbed/scene/scene.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSpecFile = fs::path(TESTBED_SOURCE_DIR) / "tests" / "data" / "in-memory.json";

json tinySpec() {
  return json::parse(R"({
    "name": "t", "citation": "test",
    "scenes": {"wall": "../../scenes/wall.json", "bunny": "../../scenes/bunny.json"},
    "settings": {"scene": "wall", "size": "160x90"},
    "columns": [{"label": "a", "shadow_map": 64}, {"label": "b", "shadow_map": 128}, {"label": "c", "scene": "bunny"}],
    "rows": [
      {"label": "SM", "techniques": ["sm"], "paper": [1, 2, 4]},
      {"label": "PF", "techniques": ["vsm", "esm"], "params": {"vsm.blur": 5}, "paper": [2, null, 8]},
      {"label": "PCF", "techniques": ["pcf"], "params": {"pcf.kernel": 5}, "paper": [3, 3, 3]},
      {"label": "SV", "techniques": ["groundtruth"], "paper": [10, 10, 10]}
    ]})");
}

// The InputError message of parsing and planning `spec`, or "" when it is valid.
std::string errorOf(const json& spec) {
  try {
    planSweep(parseSweepSpec(spec, kSpecFile), {});
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(SweepSpec, TinySpecIsValid) { EXPECT_EQ(errorOf(tinySpec()), ""); }

// The checked JSON reader's rule (io/json_reader.h), as in scene files and records.
TEST(SweepSpec, WholeNumbersMayBeWrittenAsFloats) {
  json spec = tinySpec();
  spec["columns"][0]["shadow_map"] = 64.0;
  EXPECT_EQ(errorOf(spec), "");
  EXPECT_EQ(*parseSweepSpec(spec, kSpecFile).columns[0].set.shadowMap, 64);
}

TEST(SweepSpec, MistakesNameTheFileAndTheKey) {
  struct Case {
    std::string path;  // JSON pointer to change
    json value;
    std::string expected;  // part of the message after the file name
  };
  const std::vector<Case> cases = {
      {"/colour", 1, "colour: unknown key"},
      {"/rows/1/kernel", 3, "rows[1].kernel: unknown key"},
      {"/columns/0/shadow_map", "big", "columns[0].shadow_map: expected an integer"},
      {"/columns/0/shadow_map", 0, "columns[0].shadow_map: must be an integer in [1, 16384], got 0"},
      {"/settings/size", "160by90", "settings.size: expected WxH"},
      {"/rows/0/paper", json::array({1, 2}), "rows[0].paper: expected an array of 3"},
      {"/rows/0/paper/1", "fast", "rows[0].paper[1]: expected a number or null"},
      {"/rows/2/techniques/0", "pcff", "rows[2].techniques[0]:"},
      {"/rows/2/params/pcf.kernel", 4, "rows[2] × columns[0]:"},
      {"/rows/2/params/pcf.kernels", 3, "rows[2] × columns[0]:"},
      {"/rows/2/params/kernel", 3, "rows[2].params.kernel: expected a key \"technique.name\""},
      {"/scenes/wall", "no-such-scene.json", "scenes.wall: no such scene file"},
      {"/columns/2/scene", "dragon", "columns[2].scene: 'dragon' is not in \"scenes\""},
      {"/measure", "joules", "measure: expected a metric of the metric table"},
      {"/name", "Table 2", "name: expected lower-case"},
      {"/figure", json{{"column", 7}}, "figure.column: must be an integer in [0, 2], got 7"},
  };
  for (const auto& c : cases) {
    json spec = tinySpec();
    spec[json::json_pointer(c.path)] = c.value;
    const std::string message = errorOf(spec);
    EXPECT_EQ(message.rfind(kSpecFile.string() + ": ", 0), 0u) << c.path << ": " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.path << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  json spec = tinySpec();
  spec.erase("rows");
  EXPECT_NE(errorOf(spec).find("rows: missing"), std::string::npos);
  spec = tinySpec();
  spec["settings"].erase("scene");
  EXPECT_NE(errorOf(spec).find("rows[0] × columns[0]: no scene"), std::string::npos);
}

TEST(SweepSpec, MissingOrBrokenFileIsNamed) {
  const fs::path missing = fs::temp_directory_path() / "testbed-no-such-spec.json";
  EXPECT_THROW(
      {
        try {
          loadSweepSpec(missing);
        } catch (const InputError& error) {
          EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos);
          throw;
        }
      },
      InputError);
}

TEST(SweepPlan, EqualCellsRunOnceAndEveryFrameHasItsGroundTruth) {
  const SweepPlan plan = planSweep(parseSweepSpec(tinySpec(), kSpecFile), {});
  // 3 frame set-ups (64², 128², bunny at 1024²) × (groundtruth, sm, vsm, esm, pcf): the
  // SV row times shadow volumes in every column.
  EXPECT_EQ(plan.cells.size(), 15u);
  EXPECT_EQ(plan.entries[1][0].size(), 2u);  // PF: the mean of vsm and esm
  // The wall's reference is the 64² column's ground truth for the 128² column too.
  EXPECT_EQ(plan.entries[3][0].front(), plan.cells[plan.entries[0][1].front()].truthCell);
  EXPECT_NE(plan.entries[3][1].front(), plan.cells[plan.entries[0][1].front()].truthCell);
  std::set<std::string> frames;
  std::set<std::size_t> truths;
  for (const auto& cell : plan.cells) {
    frames.insert(cell.frameKey());
    truths.insert(cell.truthCell);
    EXPECT_EQ(plan.cells[cell.truthCell].technique, "groundtruth");
    EXPECT_EQ(plan.cells[cell.truthCell].truthKey(), cell.truthKey());
  }
  EXPECT_EQ(frames.size(), 3u);
  EXPECT_EQ(truths.size(), 2u);  // wall and bunny, at 160x90
  EXPECT_EQ(plan.cells[plan.entries[2][0].front()].params.at("kernel"), "5");
  EXPECT_TRUE(plan.cells[plan.entries[1][0][1]].params.empty());  // vsm.blur is vsm's alone
}

TEST(SweepPlan, OverridesReplaceEveryLevel) {
  SweepOverrides overrides;
  overrides.shadowMap = 32;
  overrides.size = "80x45";
  const SweepPlan plan = planSweep(parseSweepSpec(tinySpec(), kSpecFile), overrides);
  for (const auto& cell : plan.cells) {
    EXPECT_EQ(cell.shadowMap, 32);
    EXPECT_EQ(cell.size, "80x45");
  }
  EXPECT_EQ(plan.cells.size(), 10u);  // the two wall columns collapse into one set-up
}

TEST(SweepShard, ShardsPartitionTheCellsExactlyOnce) {
  const SweepPlan plan = planSweep(parseSweepSpec(tinySpec(), kSpecFile), {});
  for (int n = 1; n <= 7; ++n) {
    std::vector<int> owners(plan.cells.size(), 0);
    for (int k = 1; k <= n; ++k)
      for (std::size_t i = 0; i < plan.cells.size(); ++i) owners[i] += parseShard(std::to_string(k) + "/" + std::to_string(n)).owns(i);
    for (std::size_t i = 0; i < owners.size(); ++i) EXPECT_EQ(owners[i], 1) << "cell " << i << " with " << n << " shards";
  }
}

TEST(SweepShard, BadShardsAreRejected) {
  for (const char* bad : {"3/2", "0/2", "1/0", "2", "a/b", "1/2x", "-1/2", "", "1/", "/2"}) {
    try {
      parseShard(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind("--shard: ", 0), 0u) << error.what();
    }
  }
  EXPECT_EQ(parseShard("2/3").text(), "2/3");
}

Record fakeRecord(const SweepCell& cell, double ms, double gbuffer, std::uint64_t bytes) {
  Record r;
  r.technique = cell.technique;
  r.backend = "fake";
  r.timing = TimingSource::Wall;
  r.gbufferMs = gbuffer;
  r.wall = {ms, {{"shadow-map", ms / 2}, {"visibility", ms / 2}}};
  r.memoryBytes = bytes;
  return r;
}

TEST(SweepTable, MeansRatiosAndPasses) {
  json document = tinySpec();
  document["rows"].push_back({{"label", "SM map pass"}, {"techniques", {"sm"}}, {"passes", {"gbuffer", "shadow-map"}},
                              {"paper", {1, 1, 1}}});
  document["rows"].push_back({{"label", "not ours"}, {"techniques", {"sm"}}, {"not_measured", "no such step here"},
                              {"not_measured_columns", {1}}, {"paper", {1, 1, 1}}});
  const SweepSpec spec = parseSweepSpec(document, kSpecFile);
  const SweepPlan plan = planSweep(spec, {});
  std::map<std::size_t, Record> records;
  const std::map<std::string, double> ms = {{"sm", 2}, {"vsm", 4}, {"esm", 8}, {"pcf", 6}, {"groundtruth", 20}};
  for (std::size_t i = 0; i < plan.cells.size(); ++i) records[i] = fakeRecord(plan.cells[i], ms.at(plan.cells[i].technique), 1, 1 << 20);
  const SweepTable table = buildSweepTable(spec, plan, records);
  ASSERT_EQ(table.rows.size(), 6u);
  EXPECT_TRUE(table.hasRatios);
  EXPECT_DOUBLE_EQ(*table.rows[0].ours[0], 3.0);        // G-buffer 1 + technique 2
  EXPECT_DOUBLE_EQ(*table.rows[1].ours[0], (5.0 + 9.0) / 2);  // mean of vsm and esm frames
  EXPECT_DOUBLE_EQ(*table.rows[1].oursRatio[0], 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(*table.rows[1].paperRatio[0], 2.0);
  EXPECT_FALSE(table.rows[1].paperRatio[1]);  // the paper gives no figure there
  EXPECT_DOUBLE_EQ(*table.rows[4].ours[0], 2.0);        // gbuffer 1 + shadow-map 1
  EXPECT_TRUE(table.rows[5].ours[0].has_value());
  EXPECT_FALSE(table.rows[5].ours[1].has_value());      // not measured in column 1 only
  // A missing record reads as "—", never as zero.
  records.erase(plan.entries[2][1].front());
  EXPECT_FALSE(buildSweepTable(spec, plan, records).rows[2].ours[1].has_value());
  // A pass the technique lacks is an input error naming the spec's row.
  document["rows"][4]["passes"] = {"edt"};
  const SweepSpec bad = parseSweepSpec(document, kSpecFile);
  EXPECT_THROW(buildSweepTable(bad, planSweep(bad, {}), records), InputError);
}

// "differences": each row minus its sm row in the measure's unit, ours and the paper's,
// each column's beside its ratio (as the HTML page's entries have them).
TEST(SweepTable, DifferencesToSm) {
  json document = tinySpec();
  document["differences"] = true;
  const SweepSpec spec = parseSweepSpec(document, kSpecFile);
  const SweepPlan plan = planSweep(spec, {});
  std::map<std::size_t, Record> records;
  const std::map<std::string, double> ms = {{"sm", 2}, {"vsm", 4}, {"esm", 8}, {"pcf", 6}, {"groundtruth", 20}};
  for (std::size_t i = 0; i < plan.cells.size(); ++i) {
    records[i] = fakeRecord(plan.cells[i], ms.at(plan.cells[i].technique), 1, 1 << 20);
  }
  const SweepTable table = buildSweepTable(spec, plan, records);
  ASSERT_TRUE(table.hasDifferences);
  EXPECT_DOUBLE_EQ(*table.rows[1].oursDifference[0], (5.0 + 9.0) / 2 - 3.0);
  EXPECT_DOUBLE_EQ(*table.rows[1].paperDifference[0], *table.rows[1].paper[0] - *table.rows[0].paper[0]);
  EXPECT_DOUBLE_EQ(*table.rows[0].oursDifference[0], 0.0);
  const std::string md = sweepTableMarkdown(table, {});
  EXPECT_NE(md.find("| c paper | a ours ×SM | a paper ×SM | a ours −SM | a paper −SM | b ours ×SM |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| c ours ×SM | c paper ×SM | c ours −SM | c paper −SM |\n"), std::string::npos) << md;
  // The PF row's a column: 7 ms, against SM's 3 ms: ratio 2.33 beside difference 4.
  EXPECT_NE(md.find("| 2.33 | 2.00 | 4.00 | 1.00 |"), std::string::npos) << md;
  EXPECT_FALSE(buildSweepTable(parseSweepSpec(tinySpec(), kSpecFile), plan, records).hasDifferences);
  document["differences"] = "yes";
  EXPECT_THROW(parseSweepSpec(document, kSpecFile), InputError);
}

// "shading" reads the harness's shading pass (shading_ms), which no frame holds; "frame" is
// the whole frame, so EDTSM* Table 4's total is ["frame", "shading"]; the spec's passes
// with them pass the declaration check.
TEST(SweepTable, TheShadingPassAndTheWholeFrame) {
  json document = tinySpec();
  document["rows"].push_back({{"label", "SM shading"}, {"techniques", {"sm"}}, {"passes", {"shading"}}});
  document["rows"].push_back({{"label", "SM total"}, {"techniques", {"sm"}}, {"passes", {"frame", "shading"}}});
  const SweepSpec spec = parseSweepSpec(document, kSpecFile);
  EXPECT_NO_THROW(checkDeclaredPasses(spec));
  const SweepPlan plan = planSweep(spec, {});
  std::map<std::size_t, Record> records;
  for (std::size_t i = 0; i < plan.cells.size(); ++i) {
    records[i] = fakeRecord(plan.cells[i], 2, 1, 1 << 20);
    records[i].shadingMs = 0.25;
  }
  const SweepTable table = buildSweepTable(spec, plan, records);
  const std::size_t shading = table.rows.size() - 2, total = table.rows.size() - 1;
  EXPECT_DOUBLE_EQ(*table.rows[shading].ours[0], 0.25);
  EXPECT_DOUBLE_EQ(*table.rows[total].ours[0], 1.0 + 2.0 + 0.25);  // G-buffer + technique + shading
  EXPECT_DOUBLE_EQ(*table.rows[0].ours[0], 3.0);                   // a whole frame holds no shading
  // A record made before the pass was timed has no "shading": the row's error names it.
  for (auto& [cell, record] : records) record.shadingMs.reset();
  try {
    buildSweepTable(spec, plan, records);
    ADD_FAILURE() << "no error for records without shading_ms";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".passes: sm has no pass 'shading'"), std::string::npos) << e.what();
  }
  // "frame" already holds the G-buffer and every pass: nothing but "shading" may join it.
  document["rows"].back()["passes"] = {"frame", "gbuffer"};
  try {
    parseSweepSpec(document, kSpecFile);
    ADD_FAILURE() << "accepted frame + gbuffer";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("].passes: \"frame\" is the whole frame already"), std::string::npos) << e.what();
  }
}

TEST(SweepTable, MarkdownHasThePapersRowsAndColumns) {
  const SweepSpec spec = parseSweepSpec(tinySpec(), kSpecFile);
  const SweepTable table = buildSweepTable(spec, planSweep(spec, {}), {});
  const std::string md = sweepTableMarkdown(table, {{"command", "x"}, {"machine", "y"}, {"backend", "z"}});
  std::istringstream lines(md);
  int tableLines = 0;
  std::string header;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("|", 0) == 0 && ++tableLines == 1) header = line;
  EXPECT_EQ(tableLines, 2 + 4);  // header, separator, one line per row
  EXPECT_NE(header.find("a ours | a paper |"), std::string::npos) << header;
  EXPECT_NE(header.find("c ours ×SM | c paper ×SM |"), std::string::npos) << header;
  EXPECT_NE(md.find("- backend: z"), std::string::npos);
}

// Labels are the user's words: a '|', a line break or a backtick in one is escaped in the
// markdown table, not refused, and every table line keeps the header's number of cells.
TEST(SweepTable, MarkdownEscapesLabelsThatHoldTableCharacters) {
  json document = tinySpec();
  document["columns"][0]["label"] = "a | b";
  document["rows"][0]["label"] = "SM\nline two";
  document["rows"][1]["label"] = "`code` \\|";
  document["rows"][2]["group"] = "x|y";
  const SweepSpec spec = parseSweepSpec(document, kSpecFile);
  const std::string md = sweepTableMarkdown(buildSweepTable(spec, planSweep(spec, {}), {}), {});
  // Cell separators: '|' not escaped by a backslash (itself unescaped).
  auto separators = [](const std::string& line) {
    int n = 0;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '\\') ++i;
      else if (line[i] == '|') ++n;
    }
    return n;
  };
  std::istringstream lines(md);
  std::vector<std::string> table;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("|", 0) == 0) table.push_back(line);
  ASSERT_EQ(table.size(), 2u + 4u) << md;  // header, separator, one line per row
  for (const auto& line : table) EXPECT_EQ(separators(line), separators(table[0])) << line;
  EXPECT_NE(table[0].find(" a \\| b ours |"), std::string::npos) << table[0];
  EXPECT_NE(table[2].find(" SM<br>line two |"), std::string::npos) << table[2];
  EXPECT_NE(table[3].find(" \\`code\\` \\\\\\| |"), std::string::npos) << table[3];
  EXPECT_NE(table[4].find("| x\\|y |"), std::string::npos) << table[4];
}

// The bundled paper specs (paper/): one per table, shaped as in the paper.
TEST(SweepPaperSpecs, EachTableHasThePapersShape) {
  struct Shape {
    const char* name;
    std::size_t rows, columns;
  };
  const std::vector<Shape> shapes = {
      // GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
      {"gi2016-table2", 4, 4},       // Macedo & Apolinário, GI 2016, Table 2: 4 techniques × 512²..4096²
      {"gi2016-table3", 4, 3},       // Table 3: × SD, HD, Full HD
      {"gi2016-table4", 4, 3},       // Table 4: × 15 000, 100 000, 750 000 polygons
      {"gi2016-table5", 14, 4},      // Table 5: 6 + 4 + 4 rows (3×3, 10×10, 17×17) × 512²..4096²
      {"gi2016-figure9", 11, 4},     // Figure 9: memory per technique × 512²..4096²
      // EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
      // shadow mapping", Computers & Graphics 71 (2018).
      {"edtsm-star-table1", 18, 4},  // EDTSM* Table 1: 3 scenes × 6 methods × 512²..4096²
      {"edtsm-star-table2", 18, 3},  // Table 2: × 480p, 720p, 1080p
      {"edtsm-star-table3", 18, 4},  // Table 3: × kernel 7², 15², 23², 31²
      {"edtsm-star-table4", 21, 3},  // Table 4: 3 scenes × 7 steps × 480p, 720p, 1080p
      // Macedo, Teixeira, Apolinário & Agüero, "Hard Shadow Anti-Aliasing for Spot Lights in
      // a Game Engine": 3 of its 7 figures (stand-ins) × SM, RBSM.
      {"unity-spot-table3", 6, 4},  // Table 3: × 256²..2048² at 1080p
      {"unity-spot-table4", 6, 3},  // Table 4: × 720p, 1080p, 2160p at 2048²
  };
  std::set<std::string> listed;
  for (const auto& shape : shapes) {
    const fs::path file = fs::path(TESTBED_SOURCE_DIR) / "paper" / (std::string(shape.name) + ".json");
    SCOPED_TRACE(file.string());
    const SweepSpec spec = loadSweepSpec(file);
    EXPECT_EQ(spec.name, shape.name);
    const SweepTable table = buildSweepTable(spec, planSweep(spec, {}), {});
    EXPECT_EQ(table.rows.size(), shape.rows);
    EXPECT_EQ(table.columns.size(), shape.columns);
    for (const auto& row : table.rows) EXPECT_EQ(row.paper.size(), shape.columns);
    listed.insert(file.filename().string());
  }
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "paper")) {
    if (entry.path().extension() == ".json") {
      EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path() << " has no shape test";
    }
  }
}

// The papers' polygon counts (GI 2016 Tables 2-5: Dragon ≈ 100 000; Table 4: 15 000,
// 100 000, 750 000), within 10 %, counting every triangle the GPU draws.
TEST(SweepPaperSpecs, SceneTriangleCountsMatchThePapers) {
  const std::vector<std::pair<const char*, double>> counts = {
      {"gi2016_15k.json", 15000}, {"gi2016_dragon_100k.json", 100000}, {"gi2016_750k.json", 750000}};
  for (const auto& [file, paper] : counts) {
    const Scene scene = loadScene(fs::path(TESTBED_SOURCE_DIR) / "paper" / "scenes" / file);
    double triangles = 0;
    for (const auto& object : scene.objects) triangles += double(object.mesh.n_faces());
    EXPECT_NEAR(triangles, paper, 0.1 * paper) << file;
  }
}

}  // namespace
}  // namespace testbed

namespace testbed {
namespace {

// A folder of scene files as `testbed corpus` writes them (with its manifest.json).
struct SceneFolder {
  fs::path dir = fs::temp_directory_path() / ("testbed-sweep-scenes-" + std::to_string(::getpid()));
  SceneFolder() {
    fs::create_directories(dir);
    for (const char* name : {"wall.json", "bunny.json"})
      fs::copy_file(fs::path(TESTBED_SOURCE_DIR) / "scenes" / name, dir / name, fs::copy_options::overwrite_existing);
    std::ofstream(dir / "manifest.json") << "{}\n";
  }
  ~SceneFolder() { fs::remove_all(dir); }
};

json studySpec(const json& scenes) {
  return {{"name", "study"}, {"scenes", scenes}, {"settings", {{"size", "160x90"}}}, {"measure", "mismatch_pct"},
          {"axes", {{"shadow_map", {64, 128}}}}, {"techniques", {"sm", "pcf"}}};
}

TEST(SweepStudy, ScenesAsAnAxisExpandScenesTechniquesAndSizes) {
  const SceneFolder folder;
  for (const json& scenes : {json(folder.dir.string()), json((folder.dir / "*.json").string()),
                             json::array({(folder.dir / "bunny.json").string(), (folder.dir / "wall.json").string()})}) {
    const SweepSpec spec = parseSweepSpec(studySpec(scenes), kSpecFile);
    ASSERT_EQ(spec.scenes.size(), 2u) << scenes;  // the manifest is not a scene
    ASSERT_EQ(spec.columns.size(), 4u);
    EXPECT_EQ(spec.columns[0].label, "bunny · 64²");
    EXPECT_EQ(spec.columns[3].label, "wall · 128²");
    ASSERT_EQ(spec.rows.size(), 2u);
    EXPECT_EQ(spec.rows[1].label, "pcf");
    EXPECT_EQ(spec.measure.name, "mismatch_pct");
    // The expanded list is part of the spec's identity (what shards fingerprint).
    EXPECT_TRUE(spec.document["scenes"].is_object());
    EXPECT_EQ(spec.document["scene_order"], json({"bunny", "wall"}));
    const SweepPlan plan = planSweep(spec, {});
    EXPECT_EQ(plan.cells.size(), 2u + 2u * 2u * 2u);  // one ground truth per scene, not per map size
    // Re-read as a shard's spec.json, without the folder: the same plan.
    const SweepSpec again = parseSweepSpec(spec.document, kSpecFile, false);
    EXPECT_EQ(planSweep(again, {}).cells.size(), plan.cells.size());
    EXPECT_EQ(again.columns[0].label, "bunny · 64²");
  }
}

TEST(SweepStudy, RowsVaryParametersAndNeedNoPaperFigures) {
  json spec = tinySpec();
  spec["rows"] = {{{"techniques", {"pcf"}}, {"vary", {{"pcf.kernel", {3, 5, 7}}}}}, {{"techniques", {"sm"}}}};
  const SweepSpec parsed = parseSweepSpec(spec, kSpecFile);
  ASSERT_EQ(parsed.rows.size(), 4u);
  EXPECT_EQ(parsed.rows[1].label, "pcf kernel=5");
  EXPECT_EQ(parsed.rows[1].set.params.at("pcf.kernel"), "5");
  const SweepPlan plan = planSweep(parsed, {});
  EXPECT_EQ(plan.cells[plan.entries[2][0].front()].params.at("kernel"), "7");
  // Without the paper's figures the table has no paper columns.
  const std::string md = sweepTableMarkdown(buildSweepTable(parsed, plan, {}), {});
  EXPECT_EQ(md.find("paper"), std::string::npos) << md;
  EXPECT_NE(md.find("| technique | a | b | c | a ×SM |"), std::string::npos) << md;
  EXPECT_NE(md.find("Measure: `frame_ms` (ms)"), std::string::npos) << md;
}

TEST(SweepStudy, RecordsNameTheirRowAndColumn) {
  const SweepSpec spec = parseSweepSpec(tinySpec(), kSpecFile);
  const SweepPlan plan = planSweep(spec, {});
  Record record;
  record.cell = plan.entries[2][1].front();  // PCF in column b
  json j = sweepRecordJson(record, spec, plan);
  EXPECT_EQ(j["row"], "PCF");
  EXPECT_EQ(j["column"], "b");
  record.cell = plan.entries[3][0].front();  // the wall's ground truth, read by SV in column a
  j = sweepRecordJson(record, spec, plan);
  EXPECT_EQ(j["row"], "SV");
  EXPECT_EQ(j["column"], "a");
}

TEST(SweepStudy, BadScenesAndMeasuresNameTheField) {
  const SceneFolder folder;
  const fs::path empty = folder.dir / "empty";
  fs::create_directories(empty);
  struct Case {
    json spec;
    std::string expected;
  };
  json unknownMetric = studySpec(folder.dir.string());
  unknownMetric["measure"] = "joules";
  json ratio = studySpec(folder.dir.string());
  ratio["measure"] = "x_sm";
  json both = studySpec(folder.dir.string());
  both["columns"] = json::array({{{"label", "a"}}});
  const std::vector<Case> cases = {
      {studySpec((folder.dir / "missing").string()), "scenes: no such scene file or folder"},
      {studySpec((folder.dir / "*.scene").string()), "scenes: '" + (folder.dir / "*.scene").string() + "' matches no scene file"},
      {studySpec(empty.string()), "scenes: the folder " + empty.string() + " holds no scene file"},
      {studySpec(json::array({(folder.dir / "wall.json").string(), 3})), "scenes[1]: expected a string"},
      {studySpec(json::array()), "scenes: expected scene files"},
      {unknownMetric, "measure: expected a metric of the metric table (gpu_ms.total"},
      {ratio, "(a ratio to sm"},
      {both, "axes: give \"columns\" or \"axes\", not both"},
  };
  for (const auto& c : cases) {
    const std::string message = errorOf(c.spec);
    EXPECT_EQ(message.rfind(kSpecFile.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
  EXPECT_EQ(errorOf(studySpec(folder.dir.string())), "");
}

// Figures over frames (docs/paper-runs.md "Frames"): a temporal measure needs "frames";
// a series statistic reads the sequence block's mean/p95/max of a stored metric.
TEST(SweepFrames, TemporalMeasuresNeedFramesAndReadTheSequenceBlock) {
  json spec = tinySpec();
  spec["measure"] = "flicker";
  EXPECT_NE(errorOf(spec).find(": measure: \"flicker\" is a figure over frames: the spec needs \"frames\""),
            std::string::npos) << errorOf(spec);
  spec["measure"] = "rmse.p95";
  EXPECT_NE(errorOf(spec).find(": measure: \"rmse.p95\" is a figure over frames"), std::string::npos);
  spec["frames"] = "0:1:";
  EXPECT_NE(errorOf(spec).find(": frames: expected all or A:B[:STEP]"), std::string::npos) << errorOf(spec);
  spec["frames"] = "2:1";
  EXPECT_NE(errorOf(spec).find(": frames: 2:1: expected 0 <= A <= B"), std::string::npos) << errorOf(spec);
  spec["measure"] = "rmse.median";
  spec["frames"] = "all";
  EXPECT_NE(errorOf(spec).find(": measure: expected a metric"), std::string::npos) << errorOf(spec);

  spec["measure"] = "rmse.p95";
  const SweepSpec parsed = parseSweepSpec(spec, kSpecFile);
  ASSERT_TRUE(parsed.measure.overFrames());
  EXPECT_EQ(parsed.measure.digits(), metric("rmse").digits);
  EXPECT_TRUE(parsed.measure.error());
  const SweepPlan plan = planSweep(parsed, {});
  EXPECT_EQ(plan.cells.front().frames, std::optional<std::string>("all"));
  Record record;
  EXPECT_FALSE(parsed.measure.value(record).has_value());  // a one-frame record has no series
  record.sequence = json{{"series", {{"rmse", {{"mean", 0.1}, {"p95", 0.25}, {"max", 0.3}}}}},
                         {"temporal", {{"flicker", 0.02}, {"crawl_pct", 1.5}, {"crawl_missed_pct", 0.5}}}};
  EXPECT_EQ(parsed.measure.value(record), 0.25);
  EXPECT_EQ(findSweepMeasure("flicker")->value(record), 0.02);
  EXPECT_EQ(findSweepMeasure("crawl")->value(record), 1.5);
  EXPECT_EQ(findSweepMeasure("crawl_missed")->value(record), 0.5);
  EXPECT_EQ(findSweepMeasure("crawl")->unit(), "%");
  EXPECT_FALSE(findSweepMeasure("frames"));
}

}  // namespace
}  // namespace testbed
