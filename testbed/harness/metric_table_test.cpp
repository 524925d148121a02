#include "testbed/harness/metric_table.h"

#include <gtest/gtest.h>

#include <set>

#include "testbed/harness/record.h"

namespace testbed {
namespace {

Record timed(const std::string& technique, double wallMs, double gbufferMs) {
  Record r;
  r.technique = technique;
  r.timing = TimingSource::Wall;
  r.wall.totalMs = wallMs;
  r.gbufferMs = gbufferMs;
  r.memoryBytes = 3 << 20;
  r.error = ErrorMetrics{};
  r.error->mismatchPct = 0.125;
  return r;
}

TEST(MetricTable, NamesAndPathsAreUnique) {
  std::set<std::string_view> names, paths;
  for (const Metric& m : metricTable()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    if (!m.path.empty()) EXPECT_TRUE(paths.insert(m.path).second) << m.path;
    EXPECT_EQ(m.path.empty(), m.store == nullptr) << m.name << ": a stored metric is read back, a derived one not";
    if (m.check == CheckRule::Error) EXPECT_GT(m.floor, 0) << m.name;
  }
}

// Each stored metric sits at its path in a written record, and reads back to its value.
TEST(MetricTable, StoredMetricsAreWhereTheirPathSays) {
  Record r = timed("pcf", 12.5, 1.5);
  r.gpu.totalMs = 0.75;
  r.cpuMs = 20;
  r.error->softRmse = 0.0625;
  r.error->softPenumbraMae = 0.125;
  r.error->softOutsideMae = 0.03125;
  r.error->softUmbraLeak = 0.5;
  r.error->boundaryP95 = 4;
  const nlohmann::json j = r;
  const Record back = j.get<Record>();
  for (const Metric& m : metricTable()) {
    if (m.path.empty()) continue;
    SCOPED_TRACE(std::string(m.name));
    const nlohmann::json& at = j.at(nlohmann::json::json_pointer(std::string(m.path)));
    EXPECT_EQ(at.get<double>(), *m.value(r, nullptr));
    EXPECT_EQ(at.is_number_integer(), m.integer);
    EXPECT_EQ(m.value(back, nullptr), m.value(r, nullptr));
  }
}

// One metric per work counter, named as the record names it, gated pass by pass by check;
// none where nothing was counted.
TEST(MetricTable, WorkCountersAreTheWorkBlocksTotals) {
  Record r = timed("pcf", 1, 1);
  for (const WorkCounter& counter : kWorkCounters) EXPECT_FALSE(metric(counter.name).value(r, nullptr));
  EXPECT_FALSE(metric("invocations_k").value(r, nullptr));
  r.work.emplace();
  r.work->total = {1000, 20000, 3000, 7, 6};
  for (std::size_t i = 0; i < kWorkCounters.size(); ++i) {
    const Metric& m = metric(kWorkCounters[i].name);
    EXPECT_EQ(m.check, CheckRule::Work);
    EXPECT_TRUE(m.shownIn(kCounter));
    EXPECT_EQ(*m.value(r, nullptr), double(r.work->total[i]));
  }
  EXPECT_EQ(*metric("invocations_k").value(r, nullptr), 24.0);  // vertex + fragment + compute
}

TEST(MetricTable, RatiosAreAgainstSmAndTheWholeFrame) {
  const Record sm = timed("sm", 10, 10), smsr = timed("smsr", 30, 10);
  EXPECT_EQ(*metric("x_sm").value(smsr, &sm), 3);
  EXPECT_EQ(*metric("x_sm_frame").value(smsr, &sm), 2);  // (10 + 30) / (10 + 10)
  EXPECT_FALSE(metric("x_sm").value(smsr, nullptr));
  const Record zero = timed("sm", 0, 10);
  EXPECT_FALSE(metric("x_sm").value(smsr, &zero));  // sm's 0 is not a measurement
  EXPECT_EQ(*metric("frame_ms").value(smsr, nullptr), 40);
  EXPECT_EQ(*metric("fps").value(smsr, nullptr), 25);
  EXPECT_EQ(metric("fps").better, Better::Higher);
  EXPECT_EQ(*metric("memory_mb").value(smsr, nullptr), 3);
  Record none = smsr;
  none.error.reset();
  EXPECT_FALSE(metric("mismatch_pct").value(none, nullptr));
  EXPECT_THROW(metric("joules"), std::logic_error);
  EXPECT_EQ(findMetric("fps", kSweepMeasure), &metric("fps"));
  EXPECT_EQ(findMetric("rmse", kSweepMeasure), nullptr);
  EXPECT_EQ(metric("memory_mb").unit(), "MB");
}

// Every error metric names the reference it is measured against, and only those do.
TEST(MetricTable, ErrorMetricsNameTheirReference) {
  for (const Metric& m : metricTable()) {
    SCOPED_TRACE(std::string(m.name));
    const bool error = m.path.starts_with("/error/"), soft = m.name.starts_with("soft_");
    EXPECT_EQ(m.reference, !error ? MetricReference::None : soft ? MetricReference::Soft : MetricReference::Hard);
  }
  EXPECT_EQ(referenceName(metric("soft_umbra_leak").reference), "soft");
  EXPECT_EQ(referenceName(metric("leak_pct").reference), "hard");
}

// A derived figure names the metrics it comes from; a record carries each derived figure
// that needs no baseline in its "derived" block, as the table computes it, and reading the
// record recomputes it rather than trusting the block.
TEST(MetricTable, RecordsCarryTheDerivedFigures) {
  Record r = timed("pcf", 12.5, 1.5);
  r.work.emplace();
  r.work->total = {1000, 20000, 3000, 7, 6};
  nlohmann::json j = r;
  for (const Metric& m : metricTable()) {
    SCOPED_TRACE(std::string(m.name));
    EXPECT_EQ(m.path.empty() && m.check != CheckRule::Work, !m.from.empty());  // derived: has inputs
    for (std::string_view input : inputsOf(m)) EXPECT_NO_THROW(metric(input));
    const std::string path = recordPath(m);
    EXPECT_EQ(m.shownIn(kCarried), path.starts_with("/derived/"));
    if (path.empty()) {
      EXPECT_TRUE(m.name.starts_with("x_sm"));  // the ratios: no record holds its baseline
      continue;
    }
    const std::optional<double> value = m.value(r, nullptr);
    if (!value) continue;  // not measured (the soft metrics without an area reference)
    EXPECT_EQ(j.at(nlohmann::json::json_pointer(path)).get<double>(), *value);
  }
  EXPECT_EQ(j["derived"]["frame_ms"], 14.0);
  EXPECT_EQ(j["derived"]["memory_mb"], 3.0);
  EXPECT_EQ(j["derived"]["invocations_k"], 24.0);
  j["derived"]["frame_ms"] = 99.0;  // a stale block: the stored figures decide
  const Record back = j.get<Record>();
  EXPECT_EQ(*metric("frame_ms").value(back, nullptr), 14.0);
  EXPECT_EQ(nlohmann::json(back)["derived"]["frame_ms"], 14.0);
}

TEST(MetricTable, BriefSummaryNamesTheBriefMetrics) {
  const Record sm = timed("sm", 10, 10), smsr = timed("smsr", 15, 10);
  EXPECT_EQ(briefSummary(smsr, &sm, ", "), "15 ms, 1.5x sm, mismatch 0.125%, leak 0%, boundary 0 px");
  EXPECT_EQ(briefSummary(smsr, nullptr, ", "), "15 ms, mismatch 0.125%, leak 0%, boundary 0 px");
  Record soft = smsr;  // with the area-light reference: its RMSE and penumbra error too
  soft.error->softRmse = 0.25;
  soft.error->softPenumbraMae = 0.125;
  EXPECT_EQ(briefSummary(soft, nullptr, ", "),
            "15 ms, mismatch 0.125%, leak 0%, boundary 0 px, soft RMSE 0.25, penumbra MAE 0.125");
  EXPECT_EQ(formatFixed(std::nullopt, 2), "–");
  EXPECT_EQ(formatFixed(2.0 / 3.0, 3), "0.667");
}

}  // namespace
}  // namespace testbed
