#include "testbed/app/sequence_run.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "testbed/app/python_script.h"
#include "testbed/app/work_folder.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/harness/progress.h"
#include "testbed/io/video_writer.h"
#include "testbed/metrics/metrics.h"
#include "testbed/report/frame_sheet.h"
#include "testbed/report/report_html.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

// scripts/motion_plot.py SERIES OUTDIR.
void plotSeries(const fs::path& series, const fs::path& folder) {
  runPythonScript("motion_plot.py", {series.string(), folder.string()}, series.string());
}

}  // namespace

std::vector<std::string> sequenceOutputNames(const SequenceJob& job) {
  std::vector<std::string> names = {"sequence.json"};
  if (job.compare) names.insert(names.end(), {"report.md", "index.html"});
  for (const auto& e : job.entries) {
    const std::string& id = e.technique->info->id;
    for (const char* suffix : {"_frames.json", "_sequence.json", ".mp4"}) names.push_back(id + suffix);
    names.push_back(id + "_frames_shaded.png");
    if (job.compare) names.push_back(id + "_frames_error.png");
    if (job.compare && job.plots) names.push_back(id + "_error_over_time.png");
  }
  return names;
}

std::vector<nlohmann::json> runSequence(const SequenceJob& job, Scene& scene, FrameRunner& runner,
                                        const std::string& backend, OutputFiles& files) {
  const WorkFolder work("testbed-motion");
  const int fps = scene.animation ? scene.animation->fps : 30;
  const glm::ivec2 size = runner.settings().size;
  std::vector<std::unique_ptr<VideoWriter>> videos;
  for (const auto& entry : job.entries)  // compared: shaded | error heat map; otherwise the shaded image alone
    videos.push_back(std::make_unique<VideoWriter>(work.path() / (entry.technique->info->id + ".mp4"),
                                                   size.x * (job.compare ? 2 : 1), size.y, fps));
  // Every frame also kept, shrunk, on sheets (report/frame_sheet.h): the shaded image, and
  // when compared the error heat map, for the page's frame viewer and for looking at one
  // frame without a video decoder.
  std::vector<FrameSheet> shadedSheets, errorSheets;
  for (std::size_t e = 0; e < job.entries.size(); ++e) {
    const std::string& id = job.entries[e].technique->info->id;
    shadedSheets.emplace_back(size, job.range.count(), 3, work.path() / (id + "_frames_shaded.raw"));
    if (job.compare) errorSheets.emplace_back(size, job.range.count(), 3, work.path() / (id + "_frames_error.raw"));
  }
  const auto addVideoFrame = [&](const SequenceFrame& f) {
    const ImageF shaded = runner.shade(f.run->visibility);
    shadedSheets[f.entry].add(f.index, shaded);
    if (!f.truth) return videos[f.entry]->addFrame(shaded);
    const ImageF error = errorHeatMap(f.run->visibility, *f.truth);
    videos[f.entry]->addFrame(sideBySide(shaded, error));
    errorSheets[f.entry].add(f.index, error);
  };
  const std::vector<SequenceOutcome> outcomes =
      runFrames(job.entries, job.range, job.compare, scene, runner, backend, addVideoFrame);

  // After the frames: each entry's video finished, its sheets and plot written (a good part
  // of a sequence's wall time), one progress line each.
  std::vector<nlohmann::json> records;
  ProgressReporter progress(outcomes.size());
  for (std::size_t e = 0; e < outcomes.size(); ++e) {
    const std::string& id = job.entries[e].technique->info->id;
    progress.begin(id + ": encoding, frame sheets" + std::string(job.compare && job.plots ? ", plot" : ""));
    videos[e]->finish();
    files.writeText(id + ".mp4", WorkFolder::read(videos[e]->path()));
    const std::string frames = outcomes[e].frames.dump(2) + "\n";
    files.writeText(id + "_frames.json", frames);
    records.push_back(outcomes[e].record);
    files.writeText(id + "_sequence.json", records.back().dump(2) + "\n");
    files.writeImage(id + "_frames_shaded.png", shadedSheets[e].image());
    if (job.compare) files.writeImage(id + "_frames_error.png", errorSheets[e].image());
    if (job.compare && job.plots) {
      const fs::path series = work.write(id + "_frames.json", frames);
      plotSeries(series, work.path());
      files.writeText(id + "_error_over_time.png", WorkFolder::read(work.path() / (id + "_error_over_time.png")));
    }
    progress.end(": done");
  }
  files.writeText("sequence.json", nlohmann::json(records).dump(2) + "\n");
  if (job.compare) {
    std::vector<nlohmann::json> frameRecords;
    for (const auto& outcome : outcomes) frameRecords.push_back(outcome.frames);
    const SheetLayout layout = shadedSheets.front().layout();
    files.writeText("index.html", sequenceHtml(scene.name, records, job.plots, {frameRecords, layout}));
  }
  return records;
}

void runSequenceCommand(const SequenceJob& job, Scene& scene, const RenderSettings& settings,
                        const std::string& backend, const std::string& out) {
  OutputFiles files(out);
  for (const auto& name : sequenceOutputNames(job)) files.claim(name);
  auto context = createContext(backend);
  validateSettings(settings);
  FrameRunner runner(scene, settings);
  runSequence(job, scene, runner, context->description(), files);
  files.commit();
  std::cerr << "testbed: wrote " << job.entries.front().technique->info->id
            << ".mp4, _frames.json, _sequence.json, _frames_shaded.png to " << oneLine(out) << "\n";
}

}  // namespace testbed
