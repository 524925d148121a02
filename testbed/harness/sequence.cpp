#include "testbed/harness/sequence.h"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "testbed/core/error.h"
#include "testbed/core/number_text.h"
#include "testbed/harness/metric_table.h"
#include "testbed/harness/progress.h"

namespace testbed {
namespace {

bool parseInt(std::string_view text, int& value) {
  const auto number = wholeNumber<int>(text);
  if (number) value = *number;
  return number.has_value();
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, const Scene& scene) {
  const int frames = scene.animation ? scene.animation->frames : 1;
  const std::string available =
      scene.animation ? "frames 0.." + std::to_string(frames - 1) : "no animation, so frame 0 only";
  if (text == "all") return {0, frames - 1, 1};
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t colon = text.find(':', start);
    parts.push_back(std::string_view(text).substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  FrameRange range;
  if ((parts.size() != 2 && parts.size() != 3) || !parseInt(parts[0], range.first) ||
      !parseInt(parts[1], range.last) || (parts.size() == 3 && !parseInt(parts[2], range.step)))
    throw InputError("--frames: expected all or A:B[:STEP] such as 0:47 or 0:119:4, got '" + text + "'");
  if (range.step < 1) throw InputError("--frames: STEP must be >= 1, got " + std::to_string(range.step));
  if (range.first < 0 || range.last >= frames || range.first > range.last)
    throw InputError("--frames: " + text + " is outside the scene's frames (" + scene.file.string() + ": " +
                     available + ")");
  range.last = range.at(range.count() - 1);  // the last frame the step reaches
  return range;
}

FrameChange advanceTo(Scene& scene, FrameRunner& runner, int frame) {
  const FrameChange change = applyFrame(scene, frame);
  if (!change.objects.empty()) runner.objectsMoved(change.objects);
  if (change.camera || !change.objects.empty()) runner.renderGBuffer();
  runner.lightMoved();
  return change;
}

nlohmann::json SequenceSeries::addFrame(int frame, const Record& record, const TemporalFrame* temporal,
                                        const TemporalFrame* held) {
  for (const Metric& m : metricTable()) {
    if (m.path.empty()) continue;  // derived figures (ratios to sm) come from stored ones
    if (const auto value = m.value(record, nullptr)) values_[std::string(m.name)].push_back(*value);
  }
  nlohmann::json json = record;
  json["frame"] = frame;
  json["light_fit"] = "per frame";
  if (!temporal) return json;
  compared_ = true;
  std::optional<FramePairTemporal> pair;
  try {
    pair = accumulator_.addFrame(*temporal, held);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("temporal metrics of " + record.technique + " at frame " + std::to_string(frame) +
                             ": " + e.what());
  }
  if (pair)
    json["temporal"] = {{"flicker", pair->flicker},
                        {"crawl_pct", pair->crawlPct},
                        {"crawl_missed_pct", pair->crawlMissedPct},
                        {"stable_pairs", pair->stablePairs},
                        {"moved_pixels", pair->movedPixels},
                        {"held_render", pair->heldRender}};
  return json;
}

nlohmann::json SequenceSeries::sequenceRecord(const Record& last, const FrameRange& range, int fps) const {
  nlohmann::json series = nlohmann::json::object();
  for (const auto& [name, values] : values_) {
    const SeriesSummary s = summarizeSeries(values);
    series[name] = {{"mean", s.mean}, {"p95", s.p95}, {"max", s.max}};
  }
  nlohmann::json json = {
      {"technique", last.technique},
      {"scene", last.scene},
      {"params", last.params},
      {"width", last.width},
      {"height", last.height},
      {"shadow_map", last.shadowMap},
      {"depth_format", last.depthFormat},
      {"backend", last.backend},
      {"frames", {{"first", range.first}, {"last", range.last}, {"step", range.step}, {"count", range.count()}}},
      {"fps", fps},
      {"light_fit", "per frame"},
      {"series", series},
  };
  if (compared_) {
    const TemporalMetrics& t = accumulator_.result();
    json["temporal"] = {{"flicker", t.flicker},
                        {"crawl_pct", t.crawlPct},
                        {"crawl_missed_pct", t.crawlMissedPct},
                        {"stable_pairs", t.stablePairs},
                        {"moved_pixels", t.movedPixels},
                        {"frame_pairs", t.framePairs},
                        {"held_renders", t.heldRenders}};
  }
  return json;
}

std::vector<SequenceOutcome> runFrames(const std::vector<SequenceEntry>& entries, const FrameRange& range, bool compare,
                                       Scene& scene, FrameRunner& runner, const std::string& backend,
                                       const std::function<void(const SequenceFrame&)>& onFrame) {
  struct Track {
    std::unique_ptr<TechniqueSession> session;
    SequenceSeries series;
    SequenceOutcome outcome;
  };
  std::vector<Track> tracks;
  for (const auto& entry : entries)
    tracks.push_back({std::make_unique<TechniqueSession>(runner, *entry.technique, entry.parameters), {}, {}});
  const glm::ivec2 size = runner.settings().size;
  const int count = range.count();
  ProgressReporter progress{static_cast<std::size_t>(count)};
  const std::string runs = std::to_string(tracks.size()) + (tracks.size() == 1 ? " run" : " runs");
  for (int k = 0; k < count; ++k) {
    const int frame = range.at(k);
    progress.begin("frame " + std::to_string(frame) + " of " + scene.name + " (" + runs + ")");
    // The held views: every entry's visibility and the G-buffer of the previous frame's
    // scene (its light set-up as fitted then, its objects) through this frame's camera.
    std::vector<ImageF> held;
    std::optional<ImageF> heldPositions;
    if (compare && k > 0 && scene.animation) {
      const CameraDesc camera = cameraAt(*scene.animation, frame);
      if (!(camera == scene.camera)) {
        scene.camera = camera;
        runner.renderGBuffer();
        for (Track& track : tracks) {
          track.session->renderFrame();
          held.push_back(track.session->visibility());
        }
        heldPositions = runner.positions();
      }
    }
    advanceTo(scene, runner, frame);
    const glm::mat4 viewProjection = cameraTransforms(scene.camera, float(size.x) / float(size.y)).viewProjection();
    std::optional<ImageF> truth;  // compared: the first entry's visibility, this frame only
    for (std::size_t e = 0; e < tracks.size(); ++e) {
      Track& track = tracks[e];
      const TechniqueRun run = runner.run(*track.session, entries[e].parameters, k == 0);
      Record record = makeRecord(run, runner, backend);
      std::optional<TemporalFrame> temporal, heldFrame;
      if (compare) {
        if (!truth) truth = run.visibility;
        try {
          record.error = computeErrorMetrics(run.visibility, *truth);
        } catch (const std::invalid_argument& e) {
          throw std::runtime_error(record.technique + " at frame " + std::to_string(frame) + ": " + e.what());
        }
        temporal.emplace(TemporalFrame{frame, run.visibility, *truth, runner.positions(), viewProjection});
        if (heldPositions) heldFrame.emplace(TemporalFrame{frame, held[e], held.front(), *heldPositions, viewProjection});
      }
      if (onFrame) onFrame({k, frame, e, &run, truth ? &*truth : nullptr});
      track.outcome.frames.push_back(
          track.series.addFrame(frame, record, temporal ? &*temporal : nullptr, heldFrame ? &*heldFrame : nullptr));
      track.outcome.last = std::move(record);
    }
    progress.end();
  }
  const int fps = scene.animation ? scene.animation->fps : 30;
  std::vector<SequenceOutcome> outcomes;
  for (auto& track : tracks) {
    track.outcome.record = track.series.sequenceRecord(track.outcome.last, range, fps);
    outcomes.push_back(std::move(track.outcome));
  }
  return outcomes;
}

nlohmann::json sequenceBlock(const nlohmann::json& sequenceRecord) {
  nlohmann::json block = nlohmann::json::object();
  for (const char* key : {"frames", "light_fit", "series", "temporal"})
    if (sequenceRecord.contains(key)) block[key] = sequenceRecord[key];
  return block;
}

ImageF sideBySide(const ImageF& left, const ImageF& right) {
  if (left.channels != 3 || right.channels != 3 || left.height != right.height)
    throw std::invalid_argument("sideBySide: expects two RGB images of one height");
  ImageF out;
  out.width = left.width + right.width;
  out.height = left.height;
  out.channels = 3;
  out.pixels.reserve(std::size_t(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y)
    for (const ImageF* image : {&left, &right}) {
      const auto row = image->pixels.begin() + std::ptrdiff_t(std::size_t(y) * image->width * 3);
      out.pixels.insert(out.pixels.end(), row, row + std::ptrdiff_t(image->width) * 3);
    }
  return out;
}

}  // namespace testbed
