#include "testbed/report/report_html.h"

#include <gtest/gtest.h>

#include <cmath>

namespace testbed {
namespace {

ImageF lit(int width, int height) {
  return ImageF{width, height, 1, std::vector<float>(std::size_t(width) * height, 1.0f)};
}

void shadow(ImageF& image, int x0, int y0, int side) {
  for (int y = y0; y < y0 + side; ++y)
    for (int x = x0; x < x0 + side; ++x) image.pixels[std::size_t(y) * image.width + x] = 0.0f;
}

// Two techniques, each wrong in its own 4x4 block, and one block both get wrong: the windows
// are chosen on the sum, so the shared block (2 x 16 misses) comes first, then a's (16), b's (9).
TEST(ReportHtml, SharedWindowsRankBlocksByMismatchesSummedOverTechniques) {
  const ImageF truth = lit(64, 32);
  ImageF a = lit(64, 32), b = lit(64, 32);
  shadow(a, 40, 20, 4);
  shadow(b, 40, 20, 4);
  shadow(a, 4, 4, 4);
  shadow(b, 20, 8, 3);
  const auto windows = sharedWorstWindows({&a, &b}, truth, 4, 5);
  ASSERT_EQ(windows.size(), 3u);  // no fourth window holds a mismatch
  EXPECT_EQ(windows[0].x, 40);
  EXPECT_EQ(windows[0].y, 20);
  EXPECT_EQ(windows[1].x, 4);  // 16 misses before b's 9
  EXPECT_EQ(windows[1].y, 4);
  EXPECT_EQ(windows[2].size, 4);
  EXPECT_LE(std::abs(windows[2].x - 20), 1);  // b's 3x3 block inside the 4x4 window
  EXPECT_LE(std::abs(windows[2].y - 8), 1);
}

TEST(ReportHtml, BackgroundAndAgreementGiveNoWindow) {
  ImageF truth = lit(16, 16), same = lit(16, 16);
  truth.pixels[0] = NAN;
  same.pixels[0] = 0.0f;  // wrong only where the ground truth has no receiver
  EXPECT_TRUE(sharedWorstWindows({&same}, truth, 4, 3).empty());
}

// The page's data sits in a <script>: a "</script>" in any text must not end it early.
TEST(ReportHtml, DocumentKeepsScriptTextInsideItsElement) {
  const std::string page = htmlDocument("a </script> title", {"note </script><b>"},
                                        nlohmann::json::array({htmlLinks("links", {{"</script>", "x.html"}})}));
  const std::string data = page.substr(page.find("id=\"page-data\">"));
  EXPECT_EQ(data.substr(0, data.find("</script>")).find("</"), std::string::npos);
  EXPECT_NE(page.find("<title>a &lt;/script&gt; title</title>"), std::string::npos);
  EXPECT_EQ(page.find("http"), std::string::npos);  // nothing fetched from a network
}

// No text can end the data's <script> or re-open one ("<!--<script>" would make the parser
// swallow the report script after it): '<', '>', '&', U+2028 and U+2029 are escaped, and
// the data still reads back as it was given.
TEST(ReportHtml, PageDataHoldsNoMarkupAndReadsBack) {
  const std::string hostile = "<!--<script> a </script> & b \xe2\x80\xa8 \xe2\x80\xa9 -->";
  const std::string page = htmlDocument(hostile, {hostile}, nlohmann::json::array({htmlLinks(hostile, {{hostile, hostile}})}));
  const std::string open = "id=\"page-data\">";
  const std::size_t start = page.find(open) + open.size();
  const std::string data = page.substr(start, page.find("</script>", start) - start);
  for (const std::string forbidden : {"<", ">", "&", "\xe2\x80\xa8", "\xe2\x80\xa9"})
    EXPECT_EQ(data.find(forbidden), std::string::npos) << forbidden;
  const nlohmann::json parsed = nlohmann::json::parse(data);
  EXPECT_EQ(parsed["title"], hostile);
  EXPECT_EQ(parsed["notes"][0], hostile);
  EXPECT_EQ(parsed["sections"][0]["items"][0]["text"], hostile);
  // The report script and style, embedded as they are, hold none either: exactly the two
  // script elements open and close.
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = page.find(what); at != std::string::npos; at = page.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<script"), 2u);
  EXPECT_EQ(count("</script"), 2u);
  EXPECT_EQ(count("<!--"), 0u);
}

// A sweep entry shows the paper's figures only in columns that have any: a study of one's
// own shows ours alone, never "(paper –)"; a spec's differences show beside the ratio.
TEST(ReportHtml, SweepEntriesShowThePapersFiguresOnlyWhereThereAreSome) {
  auto table = [](bool paper, bool differences) {
    nlohmann::json row = {{"label", "RBSM"}, {"ours", {2.5}}, {"paper", {paper ? nlohmann::json(5.1) : nlohmann::json()}},
                          {"ours_ratio", {1.25}}, {"paper_ratio", {paper ? nlohmann::json(1.02) : nlohmann::json()}}};
    if (differences) {
      row["ours_difference"] = {0.5};
      row["paper_difference"] = {0.1};
    }
    return nlohmann::json{{"title", "t"}, {"unit", "ms"}, {"columns", {"1024²"}}, {"paper_columns", {paper}},
                          {"has_paper", paper}, {"rows", {row}}};
  };
  const std::string study = sweepHtml("study", {{"study", table(false, false)}}, {}, {}, {}, false);
  EXPECT_NE(study.find("2.50 · 1.25×"), std::string::npos);
  EXPECT_EQ(study.find("(paper"), std::string::npos);
  const std::string paper = sweepHtml("paper", {{"paper", table(true, true)}}, {}, {}, {}, false);
  EXPECT_NE(paper.find("2.50 (paper 5.10) · 1.25× (paper 1.02×) · +0.50 ms −SM (paper +0.10)"), std::string::npos);
}

}  // namespace
}  // namespace testbed
