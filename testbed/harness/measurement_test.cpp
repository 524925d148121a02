// The measurement loop (harness/measurement.h) and its progress lines (harness/progress.h):
// the references come first and only where missing, every run reaches the sink once in
// that order, the errors are the metrics' own against the references, and a step's line
// carries the elapsed time and ETA once a step has finished.
#include "testbed/harness/measurement.h"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "testbed/harness/progress.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed::test {
namespace {

// What std::cerr receives while it lives.
class CapturedErr {
 public:
  CapturedErr() : old_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~CapturedErr() { std::cerr.rdbuf(old_); }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::streambuf* old_;
};

TEST(ProgressReporter, TheFirstStepHasNoEtaTheOthersHaveElapsedAndEta) {
  CapturedErr err;
  ProgressReporter progress(2);
  progress.begin("sm on wall");
  progress.end(": done");
  progress.begin("pcf on wall");
  progress.end();
  const std::string text = err.text();
  const std::size_t second = text.find("[2/2] pcf on wall, elapsed ");
  EXPECT_EQ(text.find("[1/2] sm on wall: done\n"), 0u) << text;
  ASSERT_NE(second, std::string::npos) << text;
  EXPECT_NE(text.find(", ETA ", second), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n') << text;
  EXPECT_EQ(progress.step(), progress.steps());
}

MeasurementJob twoEntryJob(bool withArea) {
  MeasurementJob job;
  job.backend = "test";
  job.where = "wall";
  for (const char* id : {"sm", "pcf"}) {
    const RegisteredTechnique& t = findTechnique(id);
    job.entries.push_back({&t, resolveParameters(id, t.info->parameters, {})});
  }
  if (withArea) job.area = AreaReferenceJob{4, false, 1.5};
  return job;
}

TEST(Measurement, StepsCountOnlyTheReferencesStillMissing) {
  References references;
  const MeasurementJob job = twoEntryJob(true);
  EXPECT_EQ(measurementSteps(job, references), job.entries.size() + 2);
  references.hard = ImageF{};
  EXPECT_EQ(measurementSteps(job, references), job.entries.size() + 1);
  references.area = ImageF{};
  EXPECT_EQ(measurementSteps(job, references), job.entries.size());
  EXPECT_EQ(measurementSteps(twoEntryJob(false), References{}), job.entries.size() + 1);
}

TEST(Measurement, ReferencesFirstThenEntriesWithTheirErrorsAgainstThem) {
  sharedContext();
  const Scene scene = bundledScene("wall");
  FrameRunner runner(scene, renderSettings({96, 64}, 128));
  MeasurementJob job = twoEntryJob(true);
  job.entries.back().soft = false;  // pcf judged against the hard ground truth alone
  References references;
  std::vector<std::string> seen;
  std::vector<ImageF> visibilities;
  const auto sink = [&](const MeasuredRun& m) {
    seen.push_back(m.role == MeasuredRun::Role::Entry ? m.record.technique : "reference");
    if (m.role == MeasuredRun::Role::Entry) visibilities.push_back(m.run.visibility);
  };
  const Measurement first = measure(runner, job, references, sink, nullptr);
  ASSERT_TRUE(references.hard && references.area);
  ASSERT_TRUE(first.groundTruth.has_value());
  EXPECT_FALSE(first.area.has_value());  // rendered untimed: no record
  EXPECT_EQ(seen, (std::vector<std::string>{"reference", "sm", "pcf"}));
  ASSERT_EQ(first.entries.size(), 2u);
  // The record's error block is the metrics' own: the same record with them put in reads the same.
  Record sm = first.entries[0], pcf = first.entries[1];
  sm.error = computeErrorMetrics(visibilities[0], *references.hard, &*references.area);
  pcf.error = computeErrorMetrics(visibilities[1], *references.hard);
  EXPECT_EQ(nlohmann::json(first.entries[0]), nlohmann::json(sm));
  EXPECT_EQ(nlohmann::json(first.entries[1]), nlohmann::json(pcf));
  EXPECT_TRUE(sm.error->softRmse.has_value());
  EXPECT_FALSE(pcf.error->softRmse.has_value());
  ASSERT_TRUE(first.entries[0].areaReference.has_value());  // named: the job gave a radius
  EXPECT_EQ(first.entries[0].areaReference->samples, job.area->samples);
  EXPECT_FALSE(first.entries[1].areaReference.has_value());

  // Kept references are not rendered again: the second call runs the entries alone.
  seen.clear();
  const Measurement again = measure(runner, job, references, sink, nullptr);
  EXPECT_FALSE(again.groundTruth.has_value());
  EXPECT_EQ(seen, (std::vector<std::string>{"sm", "pcf"}));
}

}  // namespace
}  // namespace testbed::test
