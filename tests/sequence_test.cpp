// Frame sequences (render --frames A-B): a range rendered in one go, in
// independently started parts, from a checkpoint, resumed after a stop or
// through the farm scripts, gives the same frames to the bit; a stopped run
// leaves only whole frames; bad input fails with one line.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <optional>

#include "cli/checkpoint_files.hpp"
#include "cli/frame_sequence.hpp"
#include "cli/usage_error.hpp"
#include "gpu_test.hpp"
#include "io/image_io.hpp"
#include "process.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"

namespace tp::test {
namespace {

constexpr const char* kSize = "--width 48 --height 27";

// Every channel of every pixel equal (both files readable).
void expectSameImage(const std::string& a, const std::string& b) {
  const io::FloatImage x = io::readImage(a), y = io::readImage(b);
  EXPECT_EQ(x.channels, y.channels) << a << " vs " << b;
  EXPECT_TRUE(x.pixels == y.pixels) << a << " differs from " << b;
}

std::string frameFile(const ScratchDir& dir, const std::string& folder, uint32_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "f.%04u.exr", frame);
  return dir.file(folder + "/" + name);
}

// Water that comes to rest within the frames rendered (a small grid, a small
// drop and a sphere that moves a little at first: the test checks that it
// sleeps), woken again by a drop on frame kWakeFrame.
constexpr uint32_t kWakeFrame = 130;
scene::Scene sleepyScene() {
  scene::Scene s = scene::defaultScene();
  s.water.grid = 32;
  s.water.damping = 2.0f;
  s.water.drops = {{.x = 0.3f, .z = -0.2f, .radius = 0.5f, .amplitude = 0.002f},
                   {.x = -0.5f, .z = 0.4f, .radius = 0.4f, .amplitude = 0.002f, .frame = kWakeFrame}};
  s.spheres.at(0).path = {{0.0f, {0.9f, -0.25f, -0.7f}}, {0.1f, {0.8998f, -0.25f, -0.7f}}};
  return s;
}

}  // namespace

using CheckpointTest = GpuTest;

// A renderer resumed from the checkpoint of any frame renders the frames after
// it as the renderer it came from did, to the bit: through the water going to
// sleep, a scheduled drop waking it, and a moving sphere.
TEST_F(CheckpointTest, AResumedRendererDrawsTheSameFrames) {
  constexpr uint32_t kW = 16, kH = 9, kLast = kWakeFrame + 6;
  const scene::Scene scene = sleepyScene();
  render::Renderer first(ctx(), scene, kW, kH);
  std::vector<std::vector<float>> frames;
  std::vector<sim::WaterCheckpoint> checkpoints;
  std::optional<uint32_t> fellAsleep;
  for (uint32_t f = 0; f <= kLast; ++f) {
    frames.push_back(first.render({.frame = f}).rgba);
    checkpoints.push_back(first.checkpoint());
    EXPECT_EQ(checkpoints.back().frame, f);
    if (!fellAsleep && checkpoints.back().asleep) fellAsleep = f;
  }
  ASSERT_TRUE(fellAsleep && *fellAsleep + 2 < kWakeFrame)
      << "the water did not sleep before the drop that wakes it: " << fellAsleep.value_or(0);
  EXPECT_FALSE(checkpoints[kWakeFrame].asleep) << "the drop on frame " << kWakeFrame << " did not wake the water";
  const uint32_t resumeAt[] = {5, *fellAsleep - 1, *fellAsleep, *fellAsleep + 2, kWakeFrame - 1, kWakeFrame};
  for (const uint32_t k : resumeAt) {
    SCOPED_TRACE("resumed at frame " + std::to_string(k));
    render::Renderer resumed(ctx(), scene, kW, kH);
    resumed.resume(checkpoints[k]);
    for (uint32_t f = k + 1; f <= kLast; ++f) EXPECT_TRUE(resumed.render({.frame = f}).rgba == frames[f]) << f;
  }
  // The sleep state is part of what the checkpoint must hold: resumed asleep
  // as awake, the water is simulated on and the frames after differ.
  render::Renderer awake(ctx(), scene, kW, kH);
  sim::WaterCheckpoint noSleep = checkpoints[*fellAsleep];
  noSleep.asleep = false;
  noSleep.quietFrames = 0;
  awake.resume(noSleep);
  bool differs = false;
  for (uint32_t f = *fellAsleep + 1; f < kWakeFrame; ++f) differs |= awake.render({.frame = f}).rgba != frames[f];
  EXPECT_TRUE(differs);
}

// The files of a checkpoint read back to it; a checkpoint of other water is refused.
TEST_F(CheckpointTest, CheckpointFilesReadBackAndBelongToTheirWater) {
  ScratchDir dir;
  const scene::Scene scene = sleepyScene();
  render::Renderer r(ctx(), scene, 16, 9);
  for (uint32_t f = 0; f <= 4; ++f) r.render({.frame = f});
  const sim::WaterCheckpoint saved = r.checkpoint();
  const uint64_t fingerprint = app::waterFingerprint(scene);
  app::saveCheckpoint(dir.path().string(), saved, fingerprint);
  EXPECT_FALSE(app::latestCheckpoint(dir.path().string(), 3, fingerprint).has_value());
  const auto read = app::latestCheckpoint(dir.path().string(), 9, fingerprint);
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->frame, 4u);
  EXPECT_EQ(read->quietFrames, saved.quietFrames);
  EXPECT_EQ(read->asleep, saved.asleep);
  EXPECT_TRUE(read->state.u == saved.state.u && read->state.v == saved.state.v);
  // A new camera keeps the water's checkpoints good; a new wave speed does not.
  scene::Scene moved = scene;
  moved.camera.position.x += 1.0f;
  EXPECT_EQ(app::waterFingerprint(moved), fingerprint);
  scene::Scene faster = scene;
  faster.water.waveSpeed *= 2.0f;
  EXPECT_THROW(app::latestCheckpoint(dir.path().string(), 9, app::waterFingerprint(faster)), std::runtime_error);
}

// The issue's test: a range rendered in one go, and as two halves started
// independently (the second from frame 0, and again from the one go's
// checkpoint), give the same frames to the bit.
TEST(RenderSequence, OneGoEqualsIndependentlyStartedHalves) {
  ScratchDir dir;
  for (const char* folder : {"one", "halves", "resumed", "water"}) std::filesystem::create_directory(dir.file(folder));
  auto render = [&](const std::string& range, const std::string& folder, const std::string& more) {
    const ProcessResult r = runTidepool(std::string("render --validate ") + kSize + " --frames " + range + " --out " +
                                            dir.file(folder + "/f.####.exr") + " " + more,
                                        dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r;
  };
  const ProcessResult one = render("0-7", "one", "--checkpoint-every 3 --checkpoint-dir " + dir.file("water"));
  EXPECT_NE(one.out.find("frame 7 (8 of 8 to render, 8 in the range): wrote "), std::string::npos) << one.out;
  for (const char* f : {"water.000000.json", "water.000003.exr", "water.000006.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("water/") + f))) << f;
  }
  render("0-3", "halves", "");
  render("4-7", "halves", "");
  const ProcessResult resumed = render("4-7", "resumed", "--checkpoint-dir " + dir.file("water"));
  EXPECT_NE(resumed.out.find("resumed the water from checkpoint frame 3"), std::string::npos) << resumed.out;
  for (uint32_t f = 0; f <= 7; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    expectSameImage(frameFile(dir, "one", f), frameFile(dir, "halves", f));
    if (f >= 4) expectSameImage(frameFile(dir, "one", f), frameFile(dir, "resumed", f));
  }
}

// --resume renders only the frames missing or broken, and they come out as
// the one-go run's.
TEST(RenderSequence, ResumeRendersOnlyMissingOrBrokenFrames) {
  ScratchDir dir;
  std::filesystem::create_directory(dir.file("a"));
  std::filesystem::create_directory(dir.file("b"));
  const std::string args = std::string("render --validate ") + kSize + " --frames 0-5 --out ";
  ASSERT_EQ(runTidepool(args + dir.file("a/f.####.exr"), dir).exitCode, 0);
  ASSERT_EQ(runTidepool(args + dir.file("b/f.####.exr"), dir).exitCode, 0);
  std::filesystem::remove(frameFile(dir, "b", 2));
  std::filesystem::resize_file(frameFile(dir, "b", 4), 100);  // a file cut short
  writeText(frameFile(dir, "b", 5), "not an image");
  const ProcessResult r = runTidepool(args + dir.file("b/f.####.exr") + " --resume", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("frames 0-5: 3 already written, 3 to render"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("wrote " + frameFile(dir, "b", 0)), std::string::npos) << r.out;
  for (uint32_t f = 0; f <= 5; ++f) expectSameImage(frameFile(dir, "a", f), frameFile(dir, "b", f));
  const ProcessResult again = runTidepool(args + dir.file("b/f.####.exr") + " --resume", dir);
  EXPECT_NE(again.out.find("frames 0-5: all 6 already written"), std::string::npos) << again.out;
}

// SIGTERM (and SIGINT) stop the run after the frame being written: exit
// 128 + the signal, a line that says so, every frame there whole, no
// temporary file; --resume then finishes the range as one go would have.
TEST(RenderSequence, SignalsStopAfterAWholeFrame) {
  for (const int signal : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(signal == SIGTERM ? "SIGTERM" : "SIGINT");
    ScratchDir dir;
    std::filesystem::create_directory(dir.file("f"));
    const std::string pattern = dir.file("f/f.####.exr");
    // Two frames written, then the signal.
    const ProcessResult stopped = runUntilSignalled(std::string("render ") + kSize + " --frames 0-400 --out " + pattern,
                                                    dir, frameFile(dir, "f", 1), signal);
    EXPECT_EQ(stopped.exitCode, 128 + signal);
    const std::string& err = stopped.err;
    EXPECT_NE(err.find(std::string("render: stopped by ") + (signal == SIGTERM ? "SIGTERM" : "SIGINT") + " after "),
              std::string::npos)
        << err;
    size_t written = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("f"))) {
      const std::string name = e.path().filename().string();
      EXPECT_EQ(name.size(), std::string("f.0000.exr").size()) << "a temporary file was left: " << name;
      EXPECT_NO_THROW(io::readImage(e.path().string())) << name;
      ++written;
    }
    EXPECT_GE(written, 2u);
    EXPECT_LT(written, 401u);
    // The rest, resumed; then the last frames equal a run straight to them.
    const ProcessResult rest = runTidepool(
        std::string("render ") + kSize + " --frames 0-" + std::to_string(written + 2) + " --resume --out " + pattern,
        dir);
    ASSERT_EQ(rest.exitCode, 0) << rest.err;
    std::filesystem::create_directory(dir.file("g"));
    ASSERT_EQ(runTidepool(std::string("render ") + kSize + " --frames " + std::to_string(written) + "-" +
                              std::to_string(written + 2) + " --out " + dir.file("g/f.####.exr"),
                          dir)
                  .exitCode,
              0);
    for (uint32_t f = uint32_t(written); f <= written + 2; ++f)
      expectSameImage(frameFile(dir, "f", f), frameFile(dir, "g", f));
  }
}

// The farm recipes of docs/rendering.md: GNU parallel on one machine, and the Slurm
// job-array script run as its array tasks would run it; both give the frames
// of one go.
TEST(RenderSequence, FarmScriptsRenderTheFramesOfOneGo) {
  ScratchDir dir;
  for (const char* folder : {"one", "parallel", "slurm"}) std::filesystem::create_directory(dir.file(folder));
  ASSERT_EQ(
      runTidepool(std::string("render ") + kSize + " --frames 0-6 --out " + dir.file("one/f.####.exr"), dir).exitCode,
      0);
  const std::string tools = std::string(TIDEPOOL_SOURCE_DIR) + "/tools/farm/";
  const std::string exe = std::string("TIDEPOOL='") + TIDEPOOL_EXE + "' ";
  const std::string log = " >" + dir.file("farm.log") + " 2>&1";
  int status = std::system((exe + "bash '" + tools + "parallel-shot.sh' 2 0 6 3 '" + dir.file("water-p") + "' -- " +
                            kSize + " --out '" + dir.file("parallel/f.####.exr") + "'" + log)
                               .c_str());
  ASSERT_EQ(status, 0) << readText(dir.file("farm.log"));
  for (int task = 0; task <= 3; ++task) {  // task 3 lies past the shot's end: nothing to do
    status =
        std::system((exe + "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SCENE='" + TIDEPOOL_SOURCE_DIR +
                     "/scenes/default.json' LAST=6 CHUNK=3 OUT='" + dir.file("slurm/f.####.exr") + "' CHECKPOINTS='" +
                     dir.file("water-s") + "' bash '" + tools + "slurm-shot.sbatch' " + kSize + log)
                        .c_str());
    ASSERT_EQ(status, 0) << readText(dir.file("farm.log"));
  }
  for (uint32_t f = 0; f <= 6; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    expectSameImage(frameFile(dir, "one", f), frameFile(dir, "parallel", f));
    expectSameImage(frameFile(dir, "one", f), frameFile(dir, "slurm", f));
  }
}

// Each DCC's way of writing the frame number's place names the same files.
TEST(RenderSequence, FramePatternsOfEveryConventionNameTheFrame) {
  const std::pair<std::string, std::string> cases[] = {
      {"f.####.exr", "f.0007.exr"},   {"f.%04d.exr", "f.0007.exr"}, {"f.$F4.exr", "f.0007.exr"},
      {"f.##.exr", "f.07.exr"},       {"f.%02d.exr", "f.07.exr"},   {"f.$F2.exr", "f.07.exr"},
      {"f.#.exr", "f.7.exr"},         {"f.%d.exr", "f.7.exr"},      {"f.$F.exr", "f.7.exr"},
      {"f_$F3.exr", "f_007.exr"},     {"%03d/f.exr", "007/f.exr"},  {"f.$FPS.%d.exr", "f.$FPS.7.exr"},
      {"100%.##.png", "100%.07.png"},
  };
  for (const auto& [pattern, path] : cases) {
    EXPECT_NO_THROW(app::checkFramePattern(pattern, "7")) << pattern;
    EXPECT_EQ(app::framePath(pattern, 7), path) << pattern;
  }
  EXPECT_EQ(app::framePath("f.%02d.exr", 1234), "f.1234.exr");
}

// A path with no place for the frame number, or two (of one convention or
// of two), is a bad command line.
TEST(RenderSequence, FramePatternsRefuseNoneOrTwoPlaces) {
  const std::pair<std::string, std::string> cases[] = {
      {"f.exr", "needs #### where the frame number goes (or %04d or $F4"},
      {"f.%4d.exr", "needs ####"},
      {"f.$FF.exr", "needs ####"},
      {"f.####.%04d.exr", "has two places for the frame number, #### and %04d: keep one"},
      {"f.$F4.####.exr", "$F4 and ####"},
      {"take#2/f.####.exr", "# and ####"},
      {"f.%d.%02d.exr", "%d and %02d"},
  };
  for (const auto& [pattern, says] : cases) {
    try {
      app::checkFramePattern(pattern, "0-3");
      ADD_FAILURE() << pattern << " was taken";
    } catch (const app::UsageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("--frames 0-3: the output " + pattern), std::string::npos) << what;
      EXPECT_NE(what.find(says), std::string::npos) << what;
    }
  }
}

TEST(RenderSequence, RefusesBadInputWithOneLine) {
  ScratchDir dir;
  std::filesystem::create_directory(dir.file("water"));
  writeText(dir.file("water/water.000000.json"),
            "{\"frame\": 0, \"quiet_frames\": 0, \"asleep\": false, \"water_fingerprint\": 1}\n");
  writeText(dir.file("water/water.000000.exr"), "x");
  std::vector<std::string> files{"water"};
  const std::string out = " --out " + dir.file("f.####.exr");
  const std::pair<std::string, std::string> cases[] = {
      {"--frames 5-2" + out, "--frames 5-2: expected A-B"},
      {"--frames x" + out, "--frames x: expected A-B"},
      {"--frames 1-" + out, "--frames 1-: expected A-B"},
      {"--frames 0-3 --out " + dir.file("f.exr"), "needs #### where the frame number goes"},
      {"--frames 0-3 --png " + dir.file("f.png") + out, "the output " + dir.file("f.png") + " needs ####"},
      {"--frames 0-3 --out /dev/null/f.####.exr", "/dev/null is not a folder"},
      {"--frames 0-3 --checkpoint-every 2" + out, "--checkpoint-every needs --checkpoint-dir"},
      {"--frames 0-3 --checkpoint-dir " + dir.file("water/water.000000.json") + out, "not a folder"},
      {"--frames 0-3 --checkpoint-dir " + dir.file("water") + out, "was made for another scene's water"},
      {"--frames 0-3 --frame 2" + out, "excludes"},
      {"--resume" + out, "--resume requires --frames"},
      {"--frames 0-1 --no-ao --aov ao" + out, "--aov ao, ao_raw and ao_ref come from the SSAO passes"},
      {"--frames 0-3 --checkpoint-every 0 --checkpoint-dir " + dir.file("water") + out, "--checkpoint-every"},
  };
  for (const auto& [args, expected] : cases) {
    const std::string line = expectCleanFailure("render " + std::string(kSize) + " " + args, dir, files);
    EXPECT_NE(line.find(expected), std::string::npos) << args << "\n" << line;
  }
}

}  // namespace tp::test
