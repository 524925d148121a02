#include "testbed/app/sequence_run.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "testbed/app/python_script.h"
#include "testbed/core/error.h"
#include "testbed/core/messages.h"
#include "testbed/gl/context.h"
#include "testbed/io/video_writer.h"
#include "testbed/metrics/metrics.h"
#include "testbed/report/report_html.h"


namespace testbed {
namespace {

namespace fs = std::filesystem;

// A private folder for what ffmpeg and matplotlib write before the files are staged.
class WorkFolder {
 public:
  WorkFolder() {
    std::string pattern = (fs::temp_directory_path() / "testbed-motion-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder in " + pattern);
    path_ = pattern;
  }
  ~WorkFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error("cannot read " + file.string());
  return bytes.str();
}

// scripts/motion_plot.py SERIES OUTDIR.
void plotSeries(const fs::path& series, const fs::path& folder) {
  runPythonScript("motion_plot.py", {series.string(), folder.string()}, series.string());
}

std::string duration(double seconds) {
  const long s = long(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  return text;
}

// One technique's state across the frames.
struct RunTrack {
  const SequenceEntry* entry = nullptr;
  std::unique_ptr<TechniqueSession> session;
  SequenceSeries series;
  nlohmann::json frames = nlohmann::json::array();
  std::optional<Record> last;
  std::unique_ptr<VideoWriter> video;
};

}  // namespace

std::vector<std::string> sequenceOutputNames(const SequenceJob& job) {
  std::vector<std::string> names = {"sequence.json"};
  if (job.compare) names.insert(names.end(), {"report.md", "index.html"});
  for (const auto& e : job.entries) {
    const std::string& id = e.technique->info->id;
    for (const char* suffix : {"_frames.json", "_sequence.json", ".mp4"}) names.push_back(id + suffix);
    if (job.compare && job.plots) names.push_back(id + "_error_over_time.png");
  }
  return names;
}

std::vector<nlohmann::json> runSequence(const SequenceJob& job, Scene& scene, FrameRunner& runner,
                                        const std::string& backend, OutputFiles& files) {
  const WorkFolder work;
  const int fps = scene.animation ? scene.animation->fps : 30;
  const glm::ivec2 size = runner.settings().size;
  std::vector<RunTrack> tracks;
  for (const auto& entry : job.entries) {
    RunTrack track;
    track.entry = &entry;
    track.session = std::make_unique<TechniqueSession>(runner, *entry.technique, entry.parameters);
    // Compared: shaded | error heat map; otherwise the shaded image alone.
    track.video = std::make_unique<VideoWriter>(work.path() / (entry.technique->info->id + ".mp4"),
                                                size.x * (job.compare ? 2 : 1), size.y, fps);
    tracks.push_back(std::move(track));
  }

  const auto start = std::chrono::steady_clock::now();
  const int count = job.range.count();
  for (int k = 0; k < count; ++k) {
    const int frame = job.range.at(k);
    advanceTo(scene, runner, frame);
    const glm::mat4 viewProjection = cameraTransforms(scene.camera, float(size.x) / float(size.y)).viewProjection();
    std::optional<ImageF> truth;  // compare: the first entry's visibility, this frame only
    for (auto& track : tracks) {
      const TechniqueRun run = runner.run(*track.session, track.entry->parameters, k == 0);
      Record record = makeRecord(run, runner, backend);
      const ImageF shaded = runner.shade(run.visibility);
      std::optional<TemporalFrame> temporal;
      if (job.compare) {
        if (!truth) truth = run.visibility;
        record.error = computeErrorMetrics(run.visibility, *truth);
        temporal.emplace(TemporalFrame{frame, run.visibility, *truth, runner.positions(), viewProjection});
        track.video->addFrame(sideBySide(shaded, errorHeatMap(run.visibility, *truth)));
      } else {
        track.video->addFrame(shaded);
      }
      track.frames.push_back(track.series.addFrame(frame, record, temporal ? &*temporal : nullptr));
      track.last = std::move(record);
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << "testbed: frame " << k + 1 << "/" << count << " (frame " << frame << " of " << oneLine(scene.name)
              << ", " << tracks.size() << (tracks.size() == 1 ? " run" : " runs") << "), elapsed "
              << duration(elapsed) << ", ETA " << duration(elapsed / (k + 1) * (count - k - 1)) << "\n";
  }

  std::vector<nlohmann::json> records;
  for (auto& track : tracks) {
    const std::string& id = track.entry->technique->info->id;
    track.video->finish();
    files.writeText(id + ".mp4", readBytes(track.video->path()));
    const std::string frames = track.frames.dump(2) + "\n";
    files.writeText(id + "_frames.json", frames);
    records.push_back(track.series.sequenceRecord(*track.last, job.range, fps));
    files.writeText(id + "_sequence.json", records.back().dump(2) + "\n");
    if (job.compare && job.plots) {
      const fs::path series = work.path() / (id + "_frames.json");
      std::ofstream(series) << frames;
      plotSeries(series, work.path());
      files.writeText(id + "_error_over_time.png", readBytes(work.path() / (id + "_error_over_time.png")));
    }
  }
  files.writeText("sequence.json", nlohmann::json(records).dump(2) + "\n");
  if (job.compare) files.writeText("index.html", sequenceHtml(scene.name, records, job.plots));
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
  std::cerr << "testbed: wrote " << job.entries.front().technique->info->id << ".mp4, _frames.json, _sequence.json to "
            << oneLine(out) << "\n";
}

}  // namespace testbed
