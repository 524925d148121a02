#include "testbed/viewer/script.h"

#include <gtest/gtest.h>

#include "testbed/core/error.h"

namespace testbed::viewer {
namespace {

TEST(ViewerScript, ParsesEveryActionSkippingCommentsAndBlankLines) {
  const auto actions = parseScript(R"(# a tour
technique pcf
set kernel=5     # as --set
set bilinear=true
orbit 30 -10
pan 12 4
zoom 0.5
light -45 5

mode error
mode debug discontinuity
shadow-map 512
depth-format 32f
frames 3
screenshot out/a.png
window-screenshot out/w.png
save-scene out/s.json
metrics out/m.json
technique smsr
set max_search=8
quit
)",
                                   "tour.txt", "sm");
  ASSERT_EQ(actions.size(), 19u);
  EXPECT_EQ(actions[0].kind, ActionKind::Technique);
  EXPECT_EQ(actions[0].text, "pcf");
  EXPECT_EQ(actions[1].text, "kernel=5");
  EXPECT_EQ(actions[1].line, 3);
  EXPECT_EQ(actions[3].kind, ActionKind::Orbit);
  EXPECT_FLOAT_EQ(actions[3].numbers[1], -10.0f);
  EXPECT_FLOAT_EQ(actions[5].numbers[0], 0.5f);
  EXPECT_EQ(actions[6].line, 8);
  EXPECT_EQ(actions[8].detail, "discontinuity");
  EXPECT_EQ(actions[9].count, 512);
  EXPECT_EQ(actions[11].count, 3);
  EXPECT_EQ(actions.back().kind, ActionKind::Quit);
}

std::string errorOf(const std::string& text, const std::string& technique = "sm", int animationFrames = 0) {
  try {
    parseScript(text, "s.txt", technique, animationFrames);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(ViewerScript, BadLinesNameTheFileAndLine) {
  EXPECT_EQ(errorOf("orbit 1 2\nspin 3\n"),
            "s.txt:2: unknown action 'spin' (actions: technique, set, orbit, pan, zoom, light, mode, shadow-map, "
            "depth-format, frames, screenshot, window-screenshot, save-scene, metrics, play, pause, step, seek, quit)");
  EXPECT_EQ(errorOf("orbit 1\n"), "s.txt:1: orbit: expected 2 argument(s), got 1");
  EXPECT_EQ(errorOf("orbit 1 nan\n"), "s.txt:1: expected two numbers: expected a finite number, got 'nan'");
  EXPECT_EQ(errorOf("zoom -2\n"), "s.txt:1: zoom: the factor must be > 0, got '-2'");
  EXPECT_EQ(errorOf("mode glow\n"), "s.txt:1: mode: expected shaded, visibility, error, soft-error or debug, got 'glow'");
  EXPECT_EQ(errorOf("frames 0\n"), "s.txt:1: frames: expected an integer in 1..100000, got '0'");
  EXPECT_EQ(errorOf("shadow-map 99999999\n"), "s.txt:1: shadow-map: expected an integer in 1..16384, got '99999999'");
  EXPECT_EQ(errorOf("screenshot a.jpg\n"), "s.txt:1: screenshot: a.jpg: the file must end in .png or .exr");
  EXPECT_EQ(errorOf("window-screenshot a.exr\n"), "s.txt:1: window-screenshot: a.exr: the file must end in .png");
  EXPECT_EQ(errorOf("save-scene a.txt\n"), "s.txt:1: save-scene: the file must end in .json, got 'a.txt'");
  EXPECT_EQ(errorOf("quit now\n"), "s.txt:1: quit: expected 0 argument(s), got 1");
  EXPECT_NE(errorOf("technique nope\n").find("s.txt:1: "), std::string::npos);
  EXPECT_NE(errorOf("depth-format 8\n").find("s.txt:1: "), std::string::npos);
}

// `set` is checked against the technique current at that line, as --set would be.
TEST(ViewerScript, SetFollowsTheCurrentTechnique) {
  EXPECT_EQ(errorOf("set kernel=5\n"), "s.txt:1: --set kernel=5: technique 'sm' has no parameter 'kernel' (its "
                                       "parameters: bias, offset_factor, offset_units)");
  EXPECT_EQ(errorOf("technique pcf\nset kernel=5\n"), "(accepted)");
  EXPECT_EQ(errorOf("technique pcf\nset kernel=4\n"), "s.txt:2: --set kernel=4: must be odd");
  EXPECT_EQ(errorOf("set kernel=5\n", "pcf"), "(accepted)");
  EXPECT_EQ(errorOf("technique pcf\ntechnique sm\nset kernel=5\n").substr(0, 8), "s.txt:3:");
}

TEST(ViewerScript, PlaybackActionsOnAnAnimatedScene) {
  const auto actions = parseScript("play\npause\nstep\nstep -3\nseek 47\n", "p.txt", "sm", 48);
  ASSERT_EQ(actions.size(), 5u);
  EXPECT_EQ(actions[0].kind, ActionKind::Play);
  EXPECT_EQ(actions[1].kind, ActionKind::Pause);
  EXPECT_EQ(actions[2].kind, ActionKind::Step);
  EXPECT_EQ(actions[2].count, 1);
  EXPECT_EQ(actions[3].count, -3);
  EXPECT_EQ(actions[4].kind, ActionKind::Seek);
  EXPECT_EQ(actions[4].count, 47);
}

TEST(ViewerScript, PlaybackActionsAreRefusedOutsideTheAnimation) {
  EXPECT_EQ(errorOf("seek 48\n", "sm", 48), "s.txt:1: seek: expected an integer in 0..47, got '48'");
  EXPECT_EQ(errorOf("step 0\n", "sm", 48), "s.txt:1: step: expected a non-zero number of frames, got 0");
  EXPECT_EQ(errorOf("step 1 2\n", "sm", 48), "s.txt:1: step: expected 0-1 argument(s), got 2");
  EXPECT_EQ(errorOf("orbit 1 2\nplay\n"),
            "s.txt:2: the scene has no animation block, so there is nothing to play, step or seek");
}

// Moves are replayed on the scene's camera and the result checked as a scene file's camera:
// finite but huge moves, which rendered an empty image, are refused naming line and field.
TEST(ViewerScript, CameraMovesThatLeaveARenderableViewAreRefused) {
  CameraDesc start;
  start.eye = {0, 30, -45};
  start.target = {0, 0, 5};
  start.farPlane = 500;
  const ScriptCamera camera{start, 360};
  auto errorFrom = [&](const std::string& text) {
    try {
      parseScript(text, "m.txt", "sm", 0, camera);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(errorFrom("orbit 720 -30\npan 300 -200\nzoom 5\nzoom 0.001\n"), "(accepted)");
  EXPECT_EQ(errorFrom("orbit 10 0\nzoom 1e30\n").rfind("m.txt:2: zoom: camera.eye: ", 0), 0u) << errorFrom("orbit 10 0\nzoom 1e30\n");
  // Zoom to 20× the distance of 58: the target lies beyond far (500), the image would be empty.
  EXPECT_EQ(errorFrom("zoom 20\n").rfind("m.txt:1: zoom: camera.target: ", 0), 0u) << errorFrom("zoom 20\n");
  // A pan of 1e30 pixels moves eye and target together out to where they round to one point.
  EXPECT_EQ(errorFrom("pan 1e30 0\n").rfind("m.txt:1: pan: camera.", 0), 0u) << errorFrom("pan 1e30 0\n");
  // Each move starts where the last left it: 2× zooms take 58 to 466 (within far 500) and
  // then to 933, refused at the fourth.
  EXPECT_EQ(errorFrom("zoom 2\nzoom 2\nzoom 2\nzoom 2\n").rfind("m.txt:4: zoom: camera.target: ", 0), 0u);
  // Without the camera (the fuzzers, older callers), moves are checked for their numbers only.
  EXPECT_EQ(errorOf("zoom 1e30\n"), "(accepted)");
}

TEST(ViewerScript, MissingFileIsAnInputError) {
  EXPECT_THROW(readScript("/nonexistent/script.txt", "sm"), InputError);
}

// A device or a folder is refused at once, naming it, not read without end.
TEST(ViewerScript, ADeviceOrAFolderIsRefusedAtOnce) {
  for (const char* file : {"/dev/zero", "/tmp"}) {
    SCOPED_TRACE(file);
    try {
      readScript(file, "sm");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(std::string("--script ") + file + ": is a ", 0), 0u) << error.what();
    }
  }
}

}  // namespace
}  // namespace testbed::viewer
