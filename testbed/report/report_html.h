#pragma once
// index.html of a run: one page that opens from the file system with no network. Its
// script and style (testbed/report/html/) are embedded at build time, its data is inline
// JSON that the script renders: sortable tables, figures, videos and, for compare, an
// image viewer (technique | reference flip and split, the error map, one zoom and pan for
// both, a pixel inspector) with close-ups of the same windows for every technique. The
// viewer's images are inline data: URIs, so the page needs none of the run's other files
// (docs/html-report.md).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "testbed/report/frame_sheet.h"
#include "testbed/report/comparison.h"

namespace testbed {

// One cell of a page's table: the text shown, the value it sorts by (none: text order,
// or last in a numeric column) and an optional link.
nlohmann::json htmlCell(const std::string& text, std::optional<double> value = std::nullopt,
                        const std::string& href = "");
struct HtmlColumn {
  std::string heading;
  bool numeric = false;
};
// How report.js shows a table beyond sorting: entries coloured by value on one scale (lower
// green, higher red), a row filter, folded away until opened or a link names one of its rows.
struct HtmlTableStyle {
  bool heat = false, filter = false, collapsed = false;
};
// Sections of a page, rendered in order by report.js.
nlohmann::json htmlTable(const std::string& title, const std::vector<std::string>& notes,
                         const std::vector<HtmlColumn>& columns, const nlohmann::json& rows,
                         const HtmlTableStyle& style = {});
// A row of htmlTable; `id` makes it a link target (#id).
nlohmann::json htmlRow(const nlohmann::json& cells, const std::string& id = "");
// A figure from a file beside index.html (hidden when the file is missing).
nlohmann::json htmlFigure(const std::string& title, const std::string& src, const std::string& href = "");
nlohmann::json htmlLinks(const std::string& title, const std::vector<std::pair<std::string, std::string>>& textAndHref);

// The whole document: title, lines under it, sections.
std::string htmlDocument(const std::string& title, const std::vector<std::string>& notes, const nlohmann::json& sections);

// A close-up window, top-left corner and side in pixels.
struct CloseUpWindow {
  int x = 0, y = 0, size = 0;
};
// Up to `count` non-overlapping `window`² squares with the most mismatching receiver pixels
// (binary at 0.5) summed over every image in `visibilities`, most first; none once no
// mismatch is left. The same windows then show every technique, as papers' close-ups do.
std::vector<CloseUpWindow> sharedWorstWindows(const std::vector<const ImageF*>& visibilities,
                                              const ImageF& groundTruth, int window, int count);

// compare's index.html: the records table, the viewer with the shared close-ups and the
// speed-vs-error plot (inline).
std::string compareHtml(const Comparison& comparison);

// What compare --frames keeps for its frame viewer: each entry's per-frame records
// (T_frames.json's, the ground truth first) and the layout of its sheets
// (T_frames_shaded.png, T_frames_error.png: report/frame_sheet.h).
struct SequenceFrames {
  std::vector<nlohmann::json> perEntry;
  SheetLayout layout;
};

// compare --frames' index.html: the sequence records table; the frame viewer (each
// technique's kept frames, stepped, scrubbed, flipped against the ground truth, its error
// map, zoomed) with every technique's error over time on one chart; and per technique its
// video (T.mp4) and error-over-time plot (T_error_over_time.png, when `plots`).
std::string sequenceHtml(const std::string& scene, const std::vector<nlohmann::json>& sequenceRecords, bool plots,
                         const SequenceFrames& frames);

// A sweep's (or merge's) index.html. `tables`: file stem → the table as sweepTableJson
// writes it (its plot is <stem>.svg beside); `entries[row][column]`: the cells a table entry
// reads (SweepPlan::entries), each entry linking to its first cell's record; `records`: every
// cell's record, one row each (#cell-N); `closeUps`: the close-up figures' file stems;
// `plots`: whether the tables' plots are drawn (--no-plot leaves them, and the page, out).
std::string sweepHtml(const std::string& name, const std::vector<std::pair<std::string, nlohmann::json>>& tables,
                      const std::vector<std::vector<std::vector<std::size_t>>>& entries,
                      const std::vector<Record>& records, const std::vector<std::string>& closeUps, bool plots);

}  // namespace testbed
