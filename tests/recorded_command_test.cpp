// Recorded commands and text set into pages (issue "hostile input, third campaign"): every
// command a run records re-runs through a shell, from another folder, to the same outputs
// and runs nothing else (an --out of `x $(touch F)` creates no F); every integer and
// frames option refuses what does not parse; names that reach a page or a Markdown file
// neither end the page's data nor split a line.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/markdown_text.h"
#include "testbed/report/sequence_report.h"
#include "testbed/sweep/sweep_table.h"
#include "tests/cli_helpers.h"
#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

using nlohmann::json;

const std::string kWall = std::string(TESTBED_SOURCE_DIR) + "/scenes/wall.json";
// An --out that runs `touch` when a recorded command holding it unquoted is pasted.
const std::string kInjectingOut = "x $(touch F)";

// `recorded` ("testbed ...") run by bash in `folder`, the testbed binary in place of "testbed".
RunResult rerun(const std::string& recorded, const fs::path& folder) {
  EXPECT_EQ(recorded.rfind("testbed ", 0), 0u) << recorded;
  const std::string line = shellQuote(TESTBED_BINARY) + recorded.substr(std::string("testbed").size());
  return runCommand({"bash", "-c", line}, {.cwd = folder});
}

// No file F anywhere a pasted command could have made it.
void expectNothingRan(const std::vector<fs::path>& folders) {
  for (const auto& folder : folders) EXPECT_FALSE(fs::exists(folder / "F")) << folder;
}

TEST(RecordedCommand, SweepsCommandIsQuotedNamesItsPluginAndReproducesTheRun) {
  TempDir tmp("recorded-sweep");
  fs::create_directories(tmp / "first");
  fs::create_directories(tmp / "again");
  const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--plugin", TESTBED_PLUGIN_EXAMPLE,
                                    "--depth-format", "24", "--no-plot", "--out", kInjectingOut},
                                   {.cwd = tmp / "first"});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const fs::path out = tmp / "first" / kInjectingOut;
  const std::string command = json::parse(readFile(out / "sweep.json")).at("command");
  EXPECT_NE(command.find("--plugin " + std::string(TESTBED_PLUGIN_EXAMPLE)), std::string::npos) << command;
  EXPECT_NE(command.find("--depth-format 24"), std::string::npos) << command;
  EXPECT_NE(command.find("'" + kInjectingOut + "'"), std::string::npos) << command;
  // The same line in the table's Markdown (escaped as Markdown text, so a '|' cannot split it).
  EXPECT_NE(readFile(out / "tiny.md").find("- command: " + markdownText(command) + "\n"), std::string::npos);

  const RunResult again = rerun(command, tmp / "again");
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  expectNothingRan({tmp / "first", tmp / "again", tmp.path()});
  EXPECT_EQ(errorsOf(json::parse(readFile(tmp / "again" / kInjectingOut / "records.json"))),
            errorsOf(json::parse(readFile(out / "records.json"))));
  EXPECT_EQ(json::parse(readFile(tmp / "again" / kInjectingOut / "sweep.json")).at("command"), command);
}

// Shard folders named like options ("-d1"): merge records "--" before them, and its
// command re-runs from another folder holding the same shards.
TEST(RecordedCommand, MergesCommandKeepsShardsThatLookLikeOptions) {
  TempDir tmp("recorded-merge");
  for (const char* folder : {"first", "again"}) {
    fs::create_directories(tmp / folder);
    for (const char* shard : {"1/2", "2/2"}) {
      const std::string name = std::string("-d") + shard[0];
      const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--shard", shard, "--out=" + name},
                                       {.cwd = tmp / folder});
      ASSERT_EQ(run.exitCode, 0) << run.describe();
    }
  }
  const RunResult merged =
      runTestbed({"merge", "--no-plot", "--out", kInjectingOut, "--", "-d1", "-d2"}, {.cwd = tmp / "first"});
  ASSERT_EQ(merged.exitCode, 0) << merged.describe();
  const fs::path out = tmp / "first" / kInjectingOut;
  const std::string command = json::parse(readFile(out / "sweep.json")).at("command");
  EXPECT_EQ(command, "testbed merge --out '" + kInjectingOut + "' --no-plot -- -d1 -d2");
  // Each shard's own command, with its "--out=-d1" kept as one word.
  for (const auto& shard : json::parse(readFile(out / "sweep.json")).at("merged_from"))
    EXPECT_NE(shard.at("command").get<std::string>().find(" --out=-d"), std::string::npos) << shard.dump();

  const RunResult again = rerun(command, tmp / "again");
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  expectNothingRan({tmp / "first", tmp / "again", tmp.path()});
  EXPECT_EQ(errorsOf(json::parse(readFile(tmp / "again" / kInjectingOut / "records.json"))),
            errorsOf(json::parse(readFile(out / "records.json"))));
}

TEST(RecordedCommand, WorstsCommandsNameEverySettingAndReproduceTheCases) {
  TempDir tmp("recorded-worst");
  fs::create_directories(tmp / "first");
  fs::create_directories(tmp / "again");
  const std::vector<std::string> args = {"worst", "--scene", kWall, "--technique", "example-sm", "--budget", "2",
                                         "--seed", "5", "--map-sizes", "64", "--size", "64x48", "--depth-format", "24",
                                         "--plugin", TESTBED_PLUGIN_EXAMPLE, "--out", kInjectingOut};
  const RunResult run = runTestbed(args, {.cwd = tmp / "first"});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const fs::path out = tmp / "first" / kInjectingOut;
  const json manifest = json::parse(readFile(out / "manifest.json"));
  const std::string command = manifest.at("command");
  EXPECT_NE(command.find("--plugin " + std::string(TESTBED_PLUGIN_EXAMPLE)), std::string::npos) << command;
  EXPECT_NE(command.find("--depth-format 24"), std::string::npos) << command;
  // The case's compare command: the setting the figure depends on, the plugin that makes it.
  const std::string compare = manifest.at("cases").at(0).at("compare");
  EXPECT_NE(compare.find("--depth-format 24"), std::string::npos) << compare;
  EXPECT_NE(compare.find("--plugin " + std::string(TESTBED_PLUGIN_EXAMPLE)), std::string::npos) << compare;

  const RunResult again = rerun(command, tmp / "again");
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  expectNothingRan({tmp / "first", tmp / "again", tmp.path()});
  const json reproduced = json::parse(readFile(tmp / "again" / kInjectingOut / "manifest.json"));
  ASSERT_EQ(reproduced.at("cases").size(), manifest.at("cases").size());
  for (std::size_t i = 0; i < manifest.at("cases").size(); ++i) {
    EXPECT_EQ(reproduced["cases"][i].at("figure"), manifest["cases"][i].at("figure")) << i;
    EXPECT_EQ(reproduced["cases"][i].at("compare"), manifest["cases"][i].at("compare")) << i;
  }

  // The case's compare command, run from the folder with an output folder of its own.
  std::string line = compare.substr(0, compare.rfind(" --out DIR")) + " --out compared";
  const RunResult compared = rerun(line, out);
  ASSERT_EQ(compared.exitCode, 0) << compared.describe();
  for (const auto& record : json::parse(readFile(out / "compared" / "metrics.json")))
    if (record.at("technique") == "example-sm")
      EXPECT_EQ(record.at("error").at("mismatch_pct"), manifest["cases"][0].at("technique_value"));
}

// One integer parser for every integer option given as text: a sign, a value past 2^64-1,
// a fraction or nothing is one line and exit 2, as corpus's --seed has always been.
TEST(RecordedCommand, IntegerAndFramesOptionsRefuseWhatDoesNotParse) {
  TempDir tmp("integer-options");
  for (const std::string seed : {"-1", "18446744073709551616", "36893488147419103232", "", "1.5", "+1", " 1", "0x10"}) {
    SCOPED_TRACE("--seed '" + seed + "'");
    const RunResult worst = runTestbed({"worst", "--scene", kWall, "--technique", "sm", "--budget", "1", "--seed", seed,
                                        "--out", (tmp / "worst").string()});
    EXPECT_TRUE(rejectedWithOneLine(worst));
    EXPECT_NE(worst.err.find("--seed: expected an integer in [0, 18446744073709551615]"), std::string::npos) << worst.err;
    const RunResult corpus = runTestbed({"corpus", "--seed", seed, "--count", "1", "--out", (tmp / "corpus").string()});
    EXPECT_TRUE(rejectedWithOneLine(corpus));
    // The same message from both commands: one parser.
    EXPECT_EQ(corpus.err, worst.err);
  }
  for (const std::string sizes : {"+64", "64,", ",64", "64,,128", "0", ""}) {
    const RunResult run = runTestbed({"worst", "--scene", kWall, "--technique", "sm", "--budget", "1", "--map-sizes",
                                      sizes, "--out", (tmp / "worst").string()});
    EXPECT_TRUE(rejectedWithOneLine(run)) << sizes;
    EXPECT_NE(run.err.find("--map-sizes: expected sizes"), std::string::npos) << run.err;
  }
  // An empty --frames is refused, never read as "not given" (frame 0 alone).
  for (const char* command : {"render", "groundtruth", "compare"}) {
    SCOPED_TRACE(command);
    std::vector<std::string> args = {command, "--scene", kWall, "--size", "64x48", "--frames", "", "--out",
                                     (tmp / command).string()};
    if (std::string(command) == "render") args.insert(args.end(), {"--technique", "sm"});
    if (std::string(command) == "compare") args.insert(args.end(), {"--techniques", "sm"});
    const RunResult run = runTestbed(args);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find("--frames: expected all or A:B[:STEP]"), std::string::npos) << run.err;
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{});
}

// A title, citation, label or scene name holding a line break, '#', '|' or markup stays in
// its own line and cell of the Markdown, and reads back as itself.
TEST(RecordedCommand, MarkdownTextNeverOpensALineOrACell) {
  const std::string hostile = "a\n# heading | cell `code` *em* [link](x) <script>_b_";
  EXPECT_EQ(markdownText(hostile), "a<br># heading \\| cell \\`code\\` \\*em\\* \\[link\\](x) &lt;script>\\_b\\_");
  EXPECT_EQ(markdownText("distance_transform"), "distance_transform");
  EXPECT_EQ(markdownCode("pass\nname | `x`"), "`` pass name \\| `x` ``");
  EXPECT_EQ(markdownCode("`edge"), "`` `edge ``");
  EXPECT_EQ(markdownCode("sm"), "`sm`");

  SweepTable table;
  table.name = "t";
  table.title = hostile;
  table.citation = hostile;
  table.measure = "frame_ms";
  table.unit = "ms";
  const std::string md = sweepTableMarkdown(table, {{"command", "testbed sweep --out '|\n# x'"}});
  std::istringstream lines(md);
  int headings = 0;
  for (std::string line; std::getline(lines, line);) {
    headings += line.rfind("#", 0) == 0;
    EXPECT_EQ(line.rfind("# heading", 0), std::string::npos) << md;
  }
  EXPECT_EQ(headings, 1) << md;
  EXPECT_EQ(md.rfind("# " + markdownText(hostile) + "\n", 0), 0u) << md;
  EXPECT_NE(md.find("- command: testbed sweep --out '\\|<br># x'\n"), std::string::npos) << md;

  const std::string sequence = sequenceMarkdown(hostile, {});
  EXPECT_EQ(sequence.rfind("# " + markdownText(hostile) + ": sequence\n", 0), 0u) << sequence;
}

// A plugin's citation and summary with line breaks and markup: `list` keeps its lines
// (the technique's line, its citation's, one per parameter) and `list --markdown` one
// row of five cells per technique, the text escaped.
TEST(RecordedCommand, PluginTextNeverSplitsAListLineOrATableRow) {
  const RunResult plain = runTestbed({"list", "--plugin", TESTBED_PLUGIN_HOSTILE_TEXT});
  ASSERT_EQ(plain.exitCode, 0) << plain.describe();
  const std::size_t at = plain.out.find(", hard]  one");  // after the plugin's id and folder
  ASSERT_NE(at, std::string::npos) << plain.out;
  // Its two lines (no parameters): up to the second line break.
  EXPECT_EQ(plain.out.substr(at, plain.out.find('\n', plain.out.find('\n', at) + 1) + 1 - at),
            ", hard]  one\\ntwo\\r\\n# three\n"
            "    Cite\\n# heading | cell `code` <script>alert(1)</script>\n");

  const RunResult md = runTestbed({"list", "--markdown", "--plugin", TESTBED_PLUGIN_HOSTILE_TEXT});
  ASSERT_EQ(md.exitCode, 0) << md.describe();
  std::istringstream lines(md.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    ASSERT_EQ(line.rfind("|", 0), 0u) << line;
    // Unescaped '|': the cell borders.
    int borders = 0;
    for (std::size_t i = 0; i < line.size(); ++i) borders += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
    EXPECT_EQ(borders, 6) << line;
    rows += line.find("`hostile-text`") != std::string::npos;
  }
  EXPECT_EQ(rows, 1) << md.out;
  EXPECT_NE(md.out.find("Cite<br># heading \\| cell \\`code\\` &lt;script>alert(1)&lt;/script>"), std::string::npos)
      << md.out;
}

// The page of a run whose scene is named like markup: its data holds no '<', '>' or '&' and
// parses back to the name (tests/html_report_test.py opens such a page in Chromium).
TEST(RecordedCommand, PageDataOfAHostileSceneNameParsesBack) {
  TempDir tmp("hostile-page");
  json scene = json::parse(readFile(kWall));
  const std::string name = "wall <!--<script> </script> & \xe2\x80\xa8";
  scene["name"] = name;
  writeFile(tmp / "scene.json", scene.dump());
  const fs::path out = tmp / "out <!--<script>";
  const RunResult run = runTestbed({"compare", "--scene", (tmp / "scene.json").string(), "--techniques", "sm",
                                    "--size", "64x48", "--shadow-map", "64", "--out", out.string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const std::string page = readFile(out / "index.html");
  const std::string open = "id=\"page-data\">";
  const std::size_t start = page.find(open) + open.size();
  const std::string data = page.substr(start, page.find("</script>", start) - start);
  for (const char* forbidden : {"<", ">", "&"}) EXPECT_EQ(data.find(forbidden), std::string::npos) << forbidden;
  EXPECT_NE(json::parse(data).dump().find(name), std::string::npos);
}

}  // namespace
}  // namespace testbed::test
