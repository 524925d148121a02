#include "testbed/report/report_html.h"

#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "testbed/harness/metric_table.h"

namespace testbed {

// testbed/report/html/report.{js,css}, embedded by cmake/EmbedText.cmake.
extern const char kReportJs[];
extern const char kReportCss[];

namespace {

using nlohmann::json;

// JSON set inside a <script> element. '<', '>' and '&' only ever occur inside JSON strings,
// where "\u003c" reads back the same: with none of them left, no "</script", "<!--" or
// "<script" can end the element or switch the HTML parser into its script-data escape
// states (HTML Living Standard, 13.2.5.4 "Script data state" onwards). U+2028/U+2029 are
// line terminators to older JavaScript parsers. scripts/page_data.py does the same.
std::string scriptSafe(const std::string& json) {
  static constexpr std::pair<std::string_view, std::string_view> kEscapes[] = {
      {"<", "\\u003c"}, {">", "\\u003e"}, {"&", "\\u0026"}, {"\xe2\x80\xa8", "\\u2028"}, {"\xe2\x80\xa9", "\\u2029"}};
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size();) {
    const auto* escape = std::find_if(std::begin(kEscapes), std::end(kEscapes),
                                      [&](const auto& e) { return json.compare(i, e.first.size(), e.first) == 0; });
    if (escape == std::end(kEscapes)) {
      out += json[i++];
    } else {
      out += escape->second;
      i += escape->first.size();
    }
  }
  return out;
}

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else if (ch == '&') out += "&amp;";
    else if (ch == '"') out += "&quot;";
    else out += ch;
  }
  return out;
}

std::string pngDataUri(const ImageF& image) {
  const std::vector<unsigned char> bytes = encodeImage("inline.png", image);
  return "data:image/png;base64," +
         OIIO::Strutil::base64_encode({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

// Visibility as an 8-bit grey + alpha PNG: grey the value (quantize8, as the T.png files
// round it), alpha 0 on the background (NaN), so the inspector reads both back.
std::string visibilityDataUri(const ImageF& visibility) {
  ImageF greyAlpha{visibility.width, visibility.height, 2, {}};
  greyAlpha.pixels.reserve(visibility.pixels.size() * 2);
  for (float v : visibility.pixels) {
    greyAlpha.pixels.push_back(std::isnan(v) ? 0.0f : v);
    greyAlpha.pixels.push_back(std::isnan(v) ? 0.0f : 1.0f);
  }
  return pngDataUri(greyAlpha);
}

// The close-up side: 48 pixels (grid.png's) where the image allows.
int closeUpSide(const ImageF& image) { return std::max(1, std::min({48, image.width / 4, image.height / 4})); }

json recordsTable(const Comparison& c) {
  std::vector<HtmlColumn> columns = {{"technique", false}};
  std::vector<const Metric*> metrics;
  for (const Metric& m : metricTable())
    if (m.shownIn(kReportColumn)) {
      metrics.push_back(&m);
      columns.push_back({std::string(m.heading), true});
    }
  json rows = json::array();
  const Record& sm = baselineRecord(c);
  for (const ComparisonEntry& entry : c.entries) {
    json cells = json::array({htmlCell(entry.record.technique, std::nullopt, entry.record.technique + ".json")});
    for (const Metric* m : metrics) {
      const std::optional<double> value = m->value(entry.record, &sm);
      cells.push_back(htmlCell(formatFixed(value, m->digits), value && std::isfinite(*value) ? value : std::nullopt));
    }
    rows.push_back(htmlRow(cells));
  }
  return htmlTable("Records", {"One row per technique (its record: the technique's name links to T.json). Click a "
                               "heading to sort. Errors are against the shadow-volume ground truth."},
                   columns, rows);
}

json viewerSection(const Comparison& c) {
  const ImageF& truth = c.groundTruthVisibility;
  std::vector<const ImageF*> visibilities;
  json techniques = json::array();
  for (const ComparisonEntry& entry : c.entries) {
    visibilities.push_back(&entry.visibility);
    techniques.push_back({{"id", entry.record.technique},
                          {"vis", visibilityDataUri(entry.visibility)},
                          {"error", pngDataUri(entry.heatMap)}});
  }
  const int side = closeUpSide(truth);
  json windows = json::array();
  for (const CloseUpWindow& w : sharedWorstWindows(visibilities, truth, side, 4))
    windows.push_back({{"x", w.x}, {"y", w.y}, {"size", w.size}});
  return {{"type", "viewer"},
          {"title", "Images"},
          {"notes", {"Visibility (black: shadow, white: lit; blue-grey: background). The error map: red and blue "
                     "where the technique is lit or shadowed and the ground truth is not, tinted where the values "
                     "differ."}},
          {"width", truth.width},
          {"height", truth.height},
          {"reference", {{"label", "ground truth"}, {"vis", visibilityDataUri(truth)}}},
          {"techniques", techniques},
          {"windows", windows},
          {"windowsNote", "The " + std::to_string(side) + "² windows with the most mismatching pixels summed over "
                          "every technique, the same windows in every row (nearest-neighbour, zoomed)."}};
}

std::optional<double> numberAt(const json& record, const std::string& pointer) {
  const json::json_pointer p(pointer);
  if (!record.contains(p) || !record.at(p).is_number()) return std::nullopt;
  return record.at(p).get<double>();
}

}  // namespace

json htmlCell(const std::string& text, std::optional<double> value, const std::string& href) {
  json cell = {{"t", text}};
  if (value && std::isfinite(*value)) cell["v"] = *value;
  if (!href.empty()) cell["href"] = href;
  return cell;
}

json htmlRow(const json& cells, const std::string& id) {
  json row = {{"cells", cells}};
  if (!id.empty()) row["id"] = id;
  return row;
}

json htmlTable(const std::string& title, const std::vector<std::string>& notes, const std::vector<HtmlColumn>& columns,
               const json& rows, const HtmlTableStyle& style) {
  json heads = json::array();
  for (const HtmlColumn& column : columns) heads.push_back({{"heading", column.heading}, {"numeric", column.numeric}});
  json table = {{"type", "table"}, {"title", title}, {"notes", notes}, {"columns", heads}, {"rows", rows}};
  if (style.heat) table["heat"] = true;
  if (style.filter) table["filter"] = true;
  if (style.collapsed) table["collapsed"] = true;
  return table;
}

json htmlFigure(const std::string& title, const std::string& src, const std::string& href) {
  json figure = {{"type", "figure"}, {"title", title}, {"src", src}};
  if (!href.empty()) figure["href"] = href;
  return figure;
}

json htmlLinks(const std::string& title, const std::vector<std::pair<std::string, std::string>>& textAndHref) {
  json items = json::array();
  for (const auto& [text, href] : textAndHref) items.push_back({{"text", text}, {"href", href}});
  return {{"type", "links"}, {"title", title}, {"items", items}};
}

std::string htmlDocument(const std::string& title, const std::vector<std::string>& notes, const json& sections) {
  const json page = {{"title", title}, {"notes", notes}, {"sections", sections}};
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<link rel=\"icon\" href=\"data:,\">\n<title>" +
         htmlEscape(title) + "</title>\n<style>\n" + kReportCss + "</style>\n</head>\n<body>\n<main id=\"main\"></main>\n" +
         "<script type=\"application/json\" id=\"page-data\">" + scriptSafe(page.dump()) + "</script>\n<script>\n" +
         kReportJs + "</script>\n</body>\n</html>\n";
}

std::vector<CloseUpWindow> sharedWorstWindows(const std::vector<const ImageF*>& visibilities, const ImageF& groundTruth,
                                              int window, int count) {
  const int w = groundTruth.width, h = groundTruth.height;
  window = std::min({window, w, h});
  if (window <= 0) return {};
  // Summed-area table of the mismatch counts makes every window's total O(1).
  std::vector<long> sum(std::size_t(w + 1) * (h + 1), 0);
  auto at = [&](int x, int y) -> long& { return sum[std::size_t(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float g = groundTruth.at(x, y);
      long misses = 0;
      for (const ImageF* v : visibilities) {
        const float value = v->at(x, y);
        misses += !std::isnan(g) && !std::isnan(value) && ((value >= 0.5f) != (g >= 0.5f));
      }
      at(x + 1, y + 1) = misses + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  std::vector<CloseUpWindow> chosen;
  auto overlaps = [&](int x, int y) {
    return std::any_of(chosen.begin(), chosen.end(), [&](const CloseUpWindow& c) {
      return std::abs(c.x - x) < window && std::abs(c.y - y) < window;
    });
  };
  while (int(chosen.size()) < count) {
    long best = 0;
    CloseUpWindow found{0, 0, window};
    for (int y = 0; y + window <= h; ++y)
      for (int x = 0; x + window <= w; ++x) {
        const long total = at(x + window, y + window) - at(x, y + window) - at(x + window, y) + at(x, y);
        if (total > best && !overlaps(x, y)) {
          best = total;
          found = {x, y, window};
        }
      }
    if (best == 0) break;
    chosen.push_back(found);
  }
  return chosen;
}

std::string compareHtml(const Comparison& c) {
  const Record& sm = baselineRecord(c);
  json sections = json::array({recordsTable(c), viewerSection(c)});
  sections.push_back({{"type", "figure"}, {"title", "Speed against error"}, {"svg", speedVsErrorSvg(c)}});
  sections.push_back(htmlLinks("Files", {{"report.md (the tables)", "report.md"},
                                         {"grid.png (each technique's own worst window)", "grid.png"},
                                         {"metrics.json (every record)", "metrics.json"},
                                         {"speed_vs_error.svg", "speed_vs_error.svg"}}));
  return htmlDocument(c.scene + ": compare",
                      {"Screen " + std::to_string(sm.width) + "×" + std::to_string(sm.height) + ", shadow map " +
                           std::to_string(sm.shadowMap) + "², " + sm.depthFormat + "-bit depth, " + sm.backend + ".",
                       "Ground truth: shadow volumes (" + formatFixed(frameTimeMs(c.groundTruth), 2) + " ms)."},
                      sections);
}

namespace {

// The frame viewer's section: every entry's sheets and its per-frame mismatch, the ground
// truth (the first entry) as the reference a technique flips against.
json frameViewer(const SequenceFrames& frames) {
  json entries = json::array();
  json numbers = json::array();
  for (const json& perFrame : frames.perEntry) {
    const std::string id = perFrame.empty() ? "?" : perFrame.front().value("technique", std::string("?"));
    json series = json::array();
    for (const json& frame : perFrame) {
      const auto value = numberAt(frame, "/error/mismatch_pct");
      series.push_back(value ? json(*value) : json());
      if (entries.empty()) numbers.push_back(frame.value("frame", 0));
    }
    entries.push_back({{"id", id}, {"shaded", id + "_frames_shaded.png"}, {"error", id + "_frames_error.png"},
                       {"series", series}});
  }
  const SheetLayout& layout = frames.layout;
  return {{"type", "frames"},
          {"title", "Frame by frame"},
          {"notes",
           {"Each technique's frames as the run kept them (" + std::to_string(layout.frameSize.x) + "×" +
            std::to_string(layout.frameSize.y) + ", 1/" + std::to_string(layout.factor) +
            " of the run's size, each pixel its block's mean; the videos below hold the full size). Keys: ← → step, "
            "Home End, f flips to the ground truth, e shows the error map, + − zoom. The chart is every technique's "
            "mismatch per frame on one scale; click it to go to a frame."}},
          {"frame", {{"width", layout.frameSize.x}, {"height", layout.frameSize.y}}},
          {"columns", layout.columns},
          {"frames", numbers},
          {"metric", "mismatch %"},
          {"entries", entries}};
}

}  // namespace

std::string sequenceHtml(const std::string& scene, const std::vector<json>& records, bool plots,
                         const SequenceFrames& frames) {
  std::vector<HtmlColumn> columns = {{"technique", false}, {"flicker", true}, {"crawl %", true},
                                     {"crawl missed %", true}, {"stable pairs", true}};
  std::vector<const Metric*> metrics;
  for (const Metric& m : metricTable())
    if (!m.path.empty() && m.shownIn(kReportColumn)) {
      metrics.push_back(&m);
      columns.push_back({std::string(m.heading) + " (mean)", true});
    }
  json rows = json::array();
  json videos = json::array();
  for (const json& r : records) {
    const std::string id = r.value("technique", std::string("?"));
    json cells = json::array({htmlCell(id, std::nullopt, id + "_sequence.json")});
    const std::pair<const char*, int> temporal[] = {
        {"flicker", 5}, {"crawl_pct", 4}, {"crawl_missed_pct", 4}, {"stable_pairs", 0}};
    for (const auto& [name, digits] : temporal) {
      const auto value = numberAt(r, "/temporal/" + std::string(name));
      cells.push_back(htmlCell(formatFixed(value, digits), value));
    }
    for (const Metric* m : metrics) {
      const auto value = numberAt(r, "/series/" + std::string(m->name) + "/mean");
      cells.push_back(htmlCell(formatFixed(value, m->digits), value));
    }
    rows.push_back(htmlRow(cells));
    json item = {{"title", id}, {"video", id + ".mp4"}};
    if (plots) item["plot"] = id + "_error_over_time.png";
    videos.push_back(item);
  }
  std::vector<std::string> notes;
  if (!records.empty() && records.front().contains("frames")) {
    const json& f = records.front().at("frames");
    notes.push_back("Frames " + f.value("first", json()).dump() + ".." + f.value("last", json()).dump() + " step " +
                    f.value("step", json()).dump() + " (" + f.value("count", json()).dump() + " frames), " +
                    records.front().value("width", json()).dump() + "×" + records.front().value("height", json()).dump() +
                    ", shadow map " + records.front().value("shadow_map", json()).dump() + "².");
  }
  const json sections = json::array(
      {htmlTable("Sequence records",
                 {"Flicker and crawl: docs/motion.md \"Temporal metrics\"; other columns: the mean over frames "
                  "(report.md has p95 and max). The technique's name links to its sequence record."},
                 columns, rows),
       frameViewer(frames),
       {{"type", "videos"},
        {"title", "Videos and error over time"},
        {"notes", {"Each video: shaded | error heat map against the ground truth, frame by frame."}},
        {"items", videos}},
       htmlLinks("Files", {{"report.md", "report.md"}, {"sequence.json (every sequence record)", "sequence.json"}})});
  return htmlDocument(scene + ": sequence", notes, sections);
}

}  // namespace testbed

namespace testbed {
namespace {

// "12.3 (paper 1.9) · 1.05× (paper 1.00×) · +0.6 ms −SM (paper +0.1)": ours beside the
// paper's, the ratio to sm and, where the spec asks, the difference to sm. A column without
// paper figures (a study of one's own) shows ours alone.
std::string sweepEntryText(const nlohmann::json& table, const nlohmann::json& row, std::size_t column) {
  auto value = [&](const char* key) -> std::optional<double> {
    const nlohmann::json& values = row.at(key);
    if (column >= values.size() || !values[column].is_number()) return std::nullopt;
    return values[column].get<double>();
  };
  auto number = [&](const char* key, int digits) { return formatFixed(value(key), digits); };
  auto signedNumber = [&](const char* key, int digits) {
    const std::optional<double> v = value(key);
    return std::string(v && *v > 0 ? "+" : "").append(formatFixed(v, digits));
  };
  const nlohmann::json paperColumns = table.value("paper_columns", nlohmann::json::array());
  const bool paper = column < paperColumns.size() && paperColumns[column].is_boolean() && paperColumns[column].get<bool>();
  auto paperPart = [&](const std::string& figure) { return paper ? " (paper " + figure + ")" : std::string(); };
  std::string text = number("ours", 2) + paperPart(number("paper", 2));
  if (row.contains("ours_ratio")) text += " · " + number("ours_ratio", 2) + "×" + paperPart(number("paper_ratio", 2) + "×");
  if (row.contains("ours_difference")) {
    const std::string unit = table.value("unit", std::string());
    text += " · " + signedNumber("ours_difference", 2) + (unit.empty() ? "" : " " + unit) + " −SM" +
            paperPart(signedNumber("paper_difference", 2));
  }
  return text;
}

nlohmann::json sweepRecordsTable(const std::vector<Record>& records) {
  // The parameters last: their JSON is long, and the size and error columns stay on screen.
  std::vector<HtmlColumn> columns = {{"cell", true}, {"scene", false},      {"technique", false},
                                     {"size", false}, {"shadow map", true}, {"depth", false}};
  std::vector<const Metric*> metrics;
  for (const Metric& m : metricTable())
    if (m.shownIn(kReportColumn) && !m.path.empty()) {
      metrics.push_back(&m);
      columns.push_back({std::string(m.heading), true});
    }
  nlohmann::json rows = nlohmann::json::array();
  for (const Record& r : records) {
    const std::string cell = r.cell ? std::to_string(*r.cell) : "";
    nlohmann::json cells = nlohmann::json::array(
        {htmlCell(cell, r.cell ? std::optional<double>(double(*r.cell)) : std::nullopt), htmlCell(r.scene),
         htmlCell(r.technique), htmlCell(std::to_string(r.width) + "×" + std::to_string(r.height)),
         htmlCell(std::to_string(r.shadowMap) + "²", r.shadowMap), htmlCell(r.depthFormat)});
    for (const Metric* m : metrics) {
      const auto value = m->value(r, nullptr);
      cells.push_back(htmlCell(formatFixed(value, m->digits), value));
    }
    cells.push_back(htmlCell(r.params.empty() ? "" : r.params.dump()));
    rows.push_back(htmlRow(cells, cell.empty() ? "" : "cell-" + cell));
  }
  columns.push_back({"parameters", false});
  return htmlTable("Cells",
                   {"Every cell's record (records.json), " + std::to_string(records.size()) +
                    " rows, folded: a table entry's link unfolds it at its cell; the filter keeps rows holding every "
                    "word typed (a scene, a technique, a map size)."},
                   columns, rows, {.filter = true, .collapsed = true});
}

}  // namespace

std::string sweepHtml(const std::string& name, const std::vector<std::pair<std::string, nlohmann::json>>& tables,
                      const std::vector<std::vector<std::vector<std::size_t>>>& entries,
                      const std::vector<Record>& records, const std::vector<std::string>& closeUps, bool plots) {
  nlohmann::json sections = nlohmann::json::array();
  std::vector<std::string> notes;
  for (const auto& [stem, table] : tables) {
    std::vector<HtmlColumn> columns = {{"row", false}};
    for (const auto& column : table.value("columns", nlohmann::json::array())) columns.push_back({column.get<std::string>(), true});
    nlohmann::json rows = nlohmann::json::array();
    const nlohmann::json& tableRows = table.at("rows");
    for (std::size_t r = 0; r < tableRows.size(); ++r) {
      const nlohmann::json& row = tableRows[r];
      nlohmann::json cells = nlohmann::json::array({htmlCell(row.value("label", std::string()))});
      for (std::size_t c = 0; c + 1 < columns.size(); ++c) {
        const nlohmann::json& ours = row.at("ours");
        const std::optional<double> value =
            c < ours.size() && ours[c].is_number() ? std::optional<double>(ours[c].get<double>()) : std::nullopt;
        const bool linked = r < entries.size() && c < entries[r].size() && !entries[r][c].empty();
        cells.push_back(htmlCell(sweepEntryText(table, row, c), value, linked ? "#cell-" + std::to_string(entries[r][c].front()) : ""));
      }
      rows.push_back(htmlRow(cells));
    }
    const std::string unit = table.value("unit", std::string());
    sections.push_back(htmlTable(table.value("title", stem) + (tables.size() > 1 ? " (" + table.value("backend", std::string()) + ")" : ""),
                                 {table.value("citation", std::string()),
                                  "Our figure" + (unit.empty() ? "" : " (" + unit + ")") +
                                      " beside the paper's; each entry links to its cell's record. " + stem + ".md holds the same table."},
                                 columns, rows));
    if (plots) sections.push_back(htmlFigure("Plot: " + stem, stem + ".svg", stem + ".png"));
    const nlohmann::json header = table.value("header", nlohmann::json::object());
    for (const auto& [key, value] : header.items())
      if (value.is_string()) notes.push_back(key + ": " + value.get<std::string>());
  }
  for (const std::string& stem : closeUps) sections.push_back(htmlFigure("Close-ups: " + stem, stem + ".png", stem + ".png"));
  sections.push_back(sweepRecordsTable(records));
  sections.push_back(htmlLinks("Files", {{"records.json", "records.json"}, {"sweep.json (how it was run)", "sweep.json"},
                                         {"spec.json", "spec.json"}}));
  return htmlDocument(name + ": sweep", notes, sections);
}

}  // namespace testbed
