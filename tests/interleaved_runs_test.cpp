// FrameRunner::runInterleaved, which `compare` times with: every technique renders one
// timed frame per round, in turn, and each gives exactly the run that run() gives it alone
// (same visibility bits, same memory), so interleaving changes when frames are timed and
// nothing else.
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed::test {
namespace {

// A technique that writes nothing and notes each frame it renders in a shared log.
class LoggingTechnique final : public ShadowTechnique {
 public:
  LoggingTechnique(std::string name, std::vector<std::string>& log) : name_(std::move(name)), log_(log) {}
  void configure(const ParameterSet&) override {}
  void render(const FrameInputs&, PassTimer& timer, const VisibilityTarget&) override {
    auto scope = timer.scope("log");
    log_.push_back(name_);
  }

 private:
  std::string name_;
  std::vector<std::string>& log_;
};

TEST(InterleavedRuns, RendersOneFrameOfEveryTechniqueInTurn) {
  sharedContext();
  const Scene scene = boxOverPlane(directional({0.3f, -1.0f, 0.2f}));
  FrameRunner runner(scene, {{32, 24}, 64, DepthFormat::D16, 3});
  std::vector<std::string> log;
  TechniqueInfo a{.id = "a"}, b{.id = "b"};
  const RegisteredTechnique first{&a, [&] { return std::make_unique<LoggingTechnique>("a", log); }};
  const RegisteredTechnique second{&b, [&] { return std::make_unique<LoggingTechnique>("b", log); }};
  std::vector<std::size_t> warmed;
  int rounds = 0;
  InterleaveProgress progress;
  progress.warmedUp = [&](std::size_t i) { warmed.push_back(i); };
  progress.round = [&](int r) { EXPECT_EQ(r, rounds++); };
  const auto runs = runner.runInterleaved({{&first, {}}, {&second, {}}}, progress);
  // A warm-up frame each, then three rounds of one frame each.
  EXPECT_EQ(log, (std::vector<std::string>{"a", "b", "a", "b", "a", "b", "a", "b"}));
  EXPECT_EQ(warmed, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(rounds, 3);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].id, "a");
  EXPECT_EQ(runs[1].id, "b");
  EXPECT_FALSE(runs[0].timedAlone);
  EXPECT_EQ(runs[0].times.wallPassMs.count("log"), 1u);
}

bool sameBits(const ImageF& x, const ImageF& y) {
  return x.width == y.width && x.height == y.height && x.channels == y.channels &&
         std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)) == 0;
}

TEST(InterleavedRuns, GiveEachTechniqueTheRunItGetsAlone) {
  sharedContext();
  const Scene scene = boxOverPlane(directional({0.3f, -1.0f, 0.2f}));
  FrameRunner runner(scene, {{96, 64}, 128, DepthFormat::D16, 2});
  // Techniques of every family, whose passes leave different GL state behind for the next.
  const std::vector<std::string> ids = {"sm", "pcf", "smsr", "rpcf-rsmss", "esm", "msm", "edtsm-star", "silhouette-map"};
  std::vector<TechniqueRequest> requests = {{&shadowVolumeGroundTruth(), resolveParameters("groundtruth", {}, {})}};
  for (const auto& id : ids) {
    const RegisteredTechnique& t = findTechnique(id);
    requests.push_back({&t, resolveParameters(id, t.info->parameters, {})});
  }
  const auto together = runner.runInterleaved(requests);
  ASSERT_EQ(together.size(), requests.size());
  for (std::size_t i = 0; i < requests.size(); ++i) {
    SCOPED_TRACE(together[i].id);
    const TechniqueRun alone = runner.run(*requests[i].technique, requests[i].parameters);
    EXPECT_EQ(together[i].id, alone.id);
    EXPECT_TRUE(sameBits(together[i].visibility, alone.visibility));
    EXPECT_EQ(together[i].memoryBytes, alone.memoryBytes);
    EXPECT_FALSE(together[i].timedAlone);
  }
}

}  // namespace
}  // namespace testbed::test
