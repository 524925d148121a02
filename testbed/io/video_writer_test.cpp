// VideoWriter through the real ffmpeg (scripts/setup.sh installs it), checked with ffprobe.
#include "testbed/io/video_writer.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

// Top half red, bottom half blue, brightening with the frame number.
ImageF frame(int w, int h, int t) {
  ImageF image{w, h, 3, {}};
  const float level = 0.5f + 0.1f * float(t);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool top = y < h / 2;
      image.pixels.insert(image.pixels.end(), {top ? level : 0.f, 0.f, top ? 0.f : level});
    }
  return image;
}

nlohmann::json probe(const fs::path& file) {
  const RunResult r = runCommand({"ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                                  "stream=codec_name,width,height,pix_fmt,color_space,nb_read_frames", "-of", "json", file.string()});
  EXPECT_EQ(r.exitCode, 0) << r.describe();
  return nlohmann::json::parse(r.out).at("streams").at(0);
}

TEST(VideoWriter, WritesH264Mp4ThatBrowsersPlay) {
  const TempDir tmp("testbed-video");
  const fs::path file = tmp.path() / "sm.mp4";
  {
    VideoWriter video(file, 33, 17, 30);  // odd sides: padded to even for yuv420p
    for (int t = 0; t < 5; ++t) video.addFrame(frame(33, 17, t));
    EXPECT_FALSE(fs::exists(file)) << "nothing at the final name before finish()";
    video.finish();
    EXPECT_EQ(video.frames(), 5);
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{"sm.mp4"}) << "no temporary left";
  const nlohmann::json stream = probe(file);
  EXPECT_EQ(stream.at("codec_name"), "h264");
  EXPECT_EQ(stream.at("pix_fmt"), "yuv420p");
  EXPECT_EQ(stream.at("color_space"), "bt709");
  EXPECT_EQ(stream.at("width"), 34);
  EXPECT_EQ(stream.at("height"), 18);
  EXPECT_EQ(stream.at("nb_read_frames"), "5");

  const std::string bytes = readFile(file);
  const auto moov = bytes.find("moov"), mdat = bytes.find("mdat");
  ASSERT_NE(moov, std::string::npos);
  ASSERT_NE(mdat, std::string::npos);
  EXPECT_LT(moov, mdat) << "+faststart puts the index first, so playback starts before the download ends";

  // The first frame decoded back: rows top-down, values quantized as PNGs are (0.5 -> 128),
  // within 8 levels (an untagged BT.601 encode reads back 140 for 128).
  const RunResult decoded = runCommand({"ffmpeg", "-v", "error", "-i", file.string(), "-frames:v", "1", "-f",
                                        "rawvideo", "-pix_fmt", "rgb24", "-"});
  ASSERT_EQ(decoded.exitCode, 0) << decoded.describe();
  ASSERT_EQ(decoded.out.size(), 34u * 18u * 3u);
  auto pixel = [&](int x, int y, int c) { return int(static_cast<unsigned char>(decoded.out[(y * 34 + x) * 3 + c])); };
  EXPECT_NEAR(pixel(4, 2, 0), 128, 8);  // top: red
  EXPECT_NEAR(pixel(4, 2, 2), 0, 8);
  EXPECT_NEAR(pixel(4, 14, 0), 0, 8);  // bottom: blue
  EXPECT_NEAR(pixel(4, 14, 2), 128, 8);
}

TEST(VideoWriter, WithoutFinishLeavesNothing) {
  const TempDir tmp("testbed-video");
  {
    VideoWriter video(tmp.path() / "sm.mp4", 16, 16, 30);
    video.addFrame(frame(16, 16, 0));
    video.addFrame(frame(16, 16, 1));
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{});
}

TEST(VideoWriter, MissingOrFailingFfmpegNamesTheFile) {
  const TempDir tmp("testbed-video");
  const fs::path file = tmp.path() / "sm.mp4";
  try {
    VideoWriter video(file, 16, 16, 30, {.ffmpeg = "testbed-no-such-ffmpeg"});
    ADD_FAILURE() << "started a program that does not exist";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("install Debian's ffmpeg"), std::string::npos) << message;
  }
  // `false` exits at once: the writes meet a closed pipe (SIGPIPE must not end the test)
  // or finish() meets its exit status.
  try {
    VideoWriter video(file, 64, 64, 30, {.ffmpeg = "false"});
    for (int t = 0; t < 20; ++t) video.addFrame(frame(64, 64, t % 5));
    video.finish();
    ADD_FAILURE() << "a failing ffmpeg went unnoticed";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{});
}

TEST(VideoWriter, BadArgumentsThrow) {
  const TempDir tmp("testbed-video");
  EXPECT_THROW(VideoWriter(tmp.path() / "sm.avi", 16, 16, 30), std::invalid_argument);
  EXPECT_THROW(VideoWriter(tmp.path() / "sm.mp4", 0, 16, 30), std::invalid_argument);
  EXPECT_THROW(VideoWriter(tmp.path() / "sm.mp4", 16, 16, 0), std::invalid_argument);
  VideoWriter video(tmp.path() / "sm.mp4", 16, 16, 30);
  EXPECT_THROW(video.addFrame(frame(16, 8, 0)), std::invalid_argument);
  ImageF grey{16, 16, 1, std::vector<float>(256, 0.5f)};
  EXPECT_THROW(video.addFrame(grey), std::invalid_argument);
}

}  // namespace
}  // namespace testbed
