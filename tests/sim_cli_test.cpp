// `tidepool sim` as a user runs it: the state it writes, resuming from it, and
// how it refuses bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "io/water_state_file.hpp"
#include "process.hpp"
#include "sim/water_state.hpp"

namespace tp::test {
namespace {

// A benchmark CSV's header line and its number of data rows.
struct CsvShape {
  std::string header;
  int rows = 0;
};

CsvShape csvShape(const std::string& path) {
  std::ifstream in(path);
  CsvShape shape;
  std::getline(in, shape.header);
  for (std::string line; std::getline(in, line);) ++shape.rows;
  return shape;
}

// A CSV line's fields; a quoted field (the device's name) may hold commas.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// A benchmark CSV's data rows, each field under its header's name.
std::vector<std::map<std::string, std::string>> csvRows(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = csvFields(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = csvFields(line);
    std::map<std::string, std::string>& row = rows.emplace_back();
    for (size_t k = 0; k < names.size() && k < fields.size(); ++k) row[names[k]] = fields[k];
  }
  return rows;
}

}  // namespace

TEST(SimCli, WritesTheStateAsAnExrOfUAndV) {
  ScratchDir dir;
  const std::string out = dir.file("state.exr");
  ProcessResult r = runTidepool("sim --validate --grid 48 --steps 20 --init mode:2,1,0.1 --out " + out, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("validation: 0 warnings, 0 errors"), std::string::npos) << r.err;
  const io::FloatImage image = io::readImage(out);
  EXPECT_EQ(image.width, 48u);
  EXPECT_EQ(image.height, 48u);
  EXPECT_EQ(image.channels, (std::vector<std::string>{"u", "v"}));
  const sim::WaterState s = io::readStateExr(out);
  float maxU = 0.0f;
  for (float u : s.u) maxU = std::max(maxU, std::abs(u));
  EXPECT_GT(maxU, 0.01f);
  EXPECT_LT(maxU, 0.1001f);
}

// 30 steps, then 20 more from the written state, equal 50 steps in one run, to the bit.
TEST(SimCli, ResumesExactlyWhereAnotherRunStopped) {
  ScratchDir dir;
  const std::string common = "sim --validate --grid 40 --dt 0.02 --damping 0.3 --boundary wrap ";
  ASSERT_EQ(runTidepool(common + "--steps 30 --init drop:0.8,1.2,0.3,0.05 --out " + dir.file("a.exr"), dir).exitCode,
            0);
  ASSERT_EQ(
      runTidepool(common + "--steps 20 --init " + dir.file("a.exr") + " --out " + dir.file("b.exr"), dir).exitCode, 0);
  ASSERT_EQ(runTidepool(common + "--steps 50 --init drop:0.8,1.2,0.3,0.05 --out " + dir.file("c.exr"), dir).exitCode,
            0);
  const auto b = io::readStateExr(dir.file("b.exr")), c = io::readStateExr(dir.file("c.exr"));
  EXPECT_EQ(b.u, c.u);
  EXPECT_EQ(b.v, c.v);
}

TEST(SimCli, BadParametersFailCleanly) {
  ScratchDir dir;
  const std::string out = " --out " + dir.file("x.exr");
  std::vector<std::string> none;
  EXPECT_NE(expectCleanFailure("sim --grid 64 --dt 0.1" + out, dir, none).find("exceeds the 2D stability bound"),
            std::string::npos);
  expectCleanFailure("sim --grid 0" + out, dir, none);
  expectCleanFailure("sim --grid -5" + out, dir, none);
  EXPECT_NE(expectCleanFailure("sim --grid 4096" + out, dir, none).find("storage buffer limit"), std::string::npos);
  expectCleanFailure("sim --grid 64", dir, none);  // no --out
  expectCleanFailure("sim --grid 64 --boundary mirror" + out, dir, none);
  expectCleanFailure("sim --grid 64 --scheme rk4" + out, dir, none);
  expectCleanFailure("sim --grid 64 --dt 0.01 --frame-time 0.02" + out, dir, none);
  EXPECT_NE(expectCleanFailure("sim --grid 64 --wave-speed nan" + out, dir, none).find("wave speed"),
            std::string::npos);
  expectCleanFailure("sim --grid 64 --extent -1" + out, dir, none);
  expectCleanFailure("sim --grid 64 --damping inf" + out, dir, none);
  expectCleanFailure("sim --grid 64 --frame-time 0" + out, dir, none);
  expectCleanFailure("sim --grid 64 --out " + dir.file("x.png"), dir, none);
  expectCleanFailure("sim --grid 64 --out /dev/null/x.exr", dir, none);
}

TEST(SimCli, BadInitialStatesFailCleanly) {
  ScratchDir dir;
  const std::string out = " --out " + dir.file("x.exr");
  // An RGBA render (no u, v channels), a u/v state of another size, a truncated EXR, text named .exr.
  ASSERT_EQ(runTidepool("render --validate --width 16 --height 16 --out " + dir.file("rgba.exr"), dir).exitCode, 0);
  ASSERT_EQ(runTidepool("sim --validate --grid 32 --steps 1 --out " + dir.file("small.exr"), dir).exitCode, 0);
  {
    std::ifstream in(dir.file("small.exr"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(dir.file("truncated.exr"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  writeText(dir.file("text.exr"), "not an image\n");
  const std::vector<std::string> files{"rgba.exr", "small.exr", "truncated.exr", "text.exr"};
  EXPECT_NE(expectCleanFailure("sim --init " + dir.file("missing.exr") + out, dir, files).find("missing.exr"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("sim --init " + dir.file("rgba.exr") + out, dir, files).find("channels u and v"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("sim --grid 64 --init " + dir.file("small.exr") + out, dir, files).find("32x32"),
            std::string::npos);
  expectCleanFailure("sim --init " + dir.file("truncated.exr") + out, dir, files);
  // The fuzzer's second finding: 592 bytes declaring 3,211,272 x 8 pixels, for
  // which OpenImageIO asked 6.5 GB; refused before any memory is taken.
  const std::string wide = std::string(TIDEPOOL_SOURCE_DIR) + "/tests/fuzz/seeds/wide-scanlines.exr";
  EXPECT_NE(expectCleanFailure("sim --init " + wide + out, dir, files).find("over the limit"), std::string::npos);
  expectCleanFailure("sim --init " + dir.file("text.exr") + out, dir, files);
  EXPECT_NE(expectCleanFailure("sim --grid 64 --init drop:1,2" + out, dir, files).find("expected 4"),
            std::string::npos);
  EXPECT_NE(expectCleanFailure("sim --grid 64 --init drop:1,2,x,4" + out, dir, files).find("'x'"), std::string::npos);
  expectCleanFailure("sim --grid 64 --init drop:1,1,0,0.1" + out, dir, files);
  expectCleanFailure("sim --grid 64 --init mode:1.5,1,0.1" + out, dir, files);
}

// The unstable scheme blows up; the run stops with an error and writes nothing.
TEST(SimCli, BlowUpStopsWithAnErrorAndNoFile) {
  ScratchDir dir;
  EXPECT_NE(expectCleanFailure(
                "sim --grid 32 --scheme explicit --steps 3000 --health-every 100 --out " + dir.file("x.exr"), dir, {})
                .find("blew up"),
            std::string::npos);
}

// The benchmark runs end to end and writes its CSV (its figures are not
// asserted: speed is a benchmark's business, not a test's).
TEST(BenchCli, SimBenchmarkWritesItsTable) {
  ScratchDir dir;
  const std::string csv = dir.file("bench.csv");
  ProcessResult r = runTidepool("bench sim --validate --sizes 16,32 --min-time 0.01 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("grid,method,", 0), 0u) << table.header;
  EXPECT_EQ(table.rows, 2 * 5);
  EXPECT_NE(r.out.find("cpu openmp"), std::string::npos);
}

TEST(BenchCli, TilesBenchmarkWritesItsTable) {
  ScratchDir dir;
  const std::string csv = dir.file("tiles.csv");
  ProcessResult r = runTidepool(
      "bench tiles --validate --sizes 32,48 --radii 0,0.3 --steps 2 --repeats 1 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("grid,drop_radius,active_fraction,ms_full,ms_active,", 0), 0u) << table.header;
  EXPECT_EQ(table.rows, 2 * 2);
}

// Seven variants, skipping off and on: fourteen rows. Bad sizes, frame counts and
// paths: one clean line, nothing written.
TEST(BenchCli, FrameBenchmarkWritesItsTableAndRefusesBadInput) {
  ScratchDir dir;
  const std::string csv = dir.file("frame.csv");
  ProcessResult r =
      runTidepool("bench frame --validate --resolution 48x32 --frames 2 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("variant,skipping,gpu_ms,wall_ms,passes,dispatches,draws,workgroups,", 0), 0u)
      << table.header;
  EXPECT_EQ(table.rows, 7 * 2);  // seven variants, skipping off and on
  ScratchDir bad;
  for (const char* size : {"48", "0x32", "5000x10"}) {
    const std::string error =
        expectCleanFailure(std::string("bench frame --resolution ") + size + " --csv " + bad.file("x.csv"), bad, {});
    EXPECT_NE(error.find(size), std::string::npos) << error;
  }
  expectCleanFailure("bench frame --frames 0 --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench frame --csv /dev/null/x.csv", bad, {});
  expectCleanFailure("bench frame --csv " + bad.file("x.txt"), bad, {});
}

// Each pass of a frame, at each resolution, timed on its own; a pass that
// ran in no timed frame (the cached sky) is not listed.
TEST(BenchCli, PassesBenchmarkWritesItsTableAndRefusesBadInput) {
  ScratchDir dir;
  const std::string csv = dir.file("passes.csv");
  ProcessResult r =
      runTidepool("bench passes --validate --resolutions 48x32,32x16 --frames 2 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header, "width,height,pass,wall_ms,gpu_ms,runs,frame_wall_ms,fps,frames,device") << table.header;
  // The default scene's frame after the first, pass by pass: simulate,
  // caustics, the ground's copy (the ground and the sky behind it are
  // cached), pool, objects, the water's four (deferred: G-buffer, tiles,
  // shading, the side from below), the resolve's tile list and the resolve
  // (the AO applied, the haze) and the HDR readback; at each of the two
  // sizes. The camera stands still: the AO made on the first frame stands.
  EXPECT_EQ(table.rows, 2 * 12);
  for (const char* pass : {"water", "simulate", "ground copy", "readback hdr"}) {
    EXPECT_NE(r.out.find(pass), std::string::npos) << pass << " missing from:\n" << r.out;
  }
  EXPECT_EQ(r.out.find("ssao"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  // A turntable moves the camera every frame: the ground and the three AO
  // passes (SSAO and the blurs) run in each.
  r = runTidepool(
      "bench passes --validate --size 32x16 --frames 2 --set camera.turntable=20 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(csvShape(csv).rows, 16);
  for (const char* pass : {"ground ", "ssao", "ao blur y"}) {
    EXPECT_NE(r.out.find(pass), std::string::npos) << pass << " missing from:\n" << r.out;
  }
  // The viewer's frame reads nothing back: the same passes less the readback.
  r = runTidepool("bench passes --validate --size 32x16 --frames 2 --shown --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(csvShape(csv).rows, 11);
  EXPECT_EQ(r.out.find("readback"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("resolve"), std::string::npos) << r.out;
  ScratchDir bad;
  for (const char* sizes : {"48", "48x32,0x32", "5000x10"}) {
    const std::string error =
        expectUsageError(std::string("bench passes --size ") + sizes + " --csv " + bad.file("x.csv"), bad, {});
    EXPECT_NE(error.find("--size: "), std::string::npos) << error;
    EXPECT_NE(error.find(" is not WxH with each side 8 to 4096"), std::string::npos) << error;
  }
  // The old spelling is checked alike, and named as the user wrote it.
  const std::string old = expectUsageError("bench passes --resolutions 48 --csv " + bad.file("x.csv"), bad, {});
  EXPECT_NE(old.find("--resolutions: 48 is not WxH"), std::string::npos) << old;
  expectCleanFailure("bench passes --frames 0 --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench passes --csv " + bad.file("x.txt"), bad, {});
}

// A sphere crossing a small pool at one speed, both immersions, both
// forcings, two kappas: a row each, the smoothness measured; the spread
// forcing once per widening, a wider bump a lower crest; bad lists refused
// with one line.
TEST(BenchCli, WakeBenchmarkWritesItsTableAndRefusesBadInput) {
  ScratchDir dir;
  const std::string csv = dir.file("wake.csv");
  ProcessResult r = runTidepool(
      "bench wake --validate --sizes 32 --speeds 0.9 --grid-dampings 0,2 --wave-speed 0.9 --csv " + csv + " --plot ''",
      dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header,
            "grid,speed_fraction,immersion,forcing,spread_depth_factor,near_speed_widening,grid_damping,slope_limit,"
            "steps,ms_per_step,high_share,max_slope,crest_m,trough_m,volume_change_m3,device")
      << table.header;
  EXPECT_EQ(table.rows, 2 * 2 * 2);
  EXPECT_NE(r.out.find("submerged"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spread"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  // The spread forcing alone on 32 cells, both immersions: two rows per
  // compared value, the value's row after the default's.
  const auto spreadRows = [&](const std::string& options) {
    const ProcessResult run = runTidepool(
        "bench wake --sizes 32 --grid-dampings 2 --forcings spread " + options + " --csv " + csv + " --plot ''", dir);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out.find("column"), std::string::npos) << run.out;
    const std::vector<std::map<std::string, std::string>> rows = csvRows(csv);
    EXPECT_EQ(rows.size(), 2u * 2u);
    return rows;
  };
  const std::vector<std::map<std::string, std::string>> rows = spreadRows("--speeds 0.5 --spread-depth-factors 0.65,4");
  for (size_t k = 0; k + 1 < rows.size(); k += 2) {
    EXPECT_EQ(rows[k].at("spread_depth_factor"), "0.65");
    EXPECT_EQ(rows[k + 1].at("spread_depth_factor"), "4");
    EXPECT_LT(std::stod(rows[k + 1].at("crest_m")), std::stod(rows[k].at("crest_m"))) << rows[k].at("immersion");
  }
  // The widening near the wave speed: once off and once on, the crest lower with it.
  const std::vector<std::map<std::string, std::string>> near = spreadRows("--speeds 0.9 --near-speed-widening off,on");
  for (size_t k = 0; k + 1 < near.size(); k += 2) {
    EXPECT_EQ(near[k].at("near_speed_widening"), "off");
    EXPECT_EQ(near[k + 1].at("near_speed_widening"), "on");
    EXPECT_LT(std::stod(near[k + 1].at("crest_m")), 0.5 * std::stod(near[k].at("crest_m"))) << near[k].at("immersion");
  }
  // The slope limiter (on the unwidened bump, whose wake is steep): once per
  // limit, the steepest slope lower with it and the volume kept.
  const std::vector<std::map<std::string, std::string>> limited =
      spreadRows("--speeds 0.9 --near-speed-widening off --max-slopes 0,0.5");
  for (size_t k = 0; k + 1 < limited.size(); k += 2) {
    EXPECT_EQ(limited[k].at("slope_limit"), "0");
    EXPECT_EQ(limited[k + 1].at("slope_limit"), "0.5");
    EXPECT_LT(std::stod(limited[k + 1].at("max_slope")), std::stod(limited[k].at("max_slope")));
    EXPECT_LT(std::abs(std::stod(limited[k + 1].at("volume_change_m3"))), 1e-6);
  }
  ScratchDir bad;
  for (const char* option : {"--sizes 8", "--speeds 0", "--grid-dampings -1", "--sizes 32,x", "--forcings chord",
                             "--spread-depth-factors -1", "--max-slopes -1", "--wave-speed 0", "--wave-speed x",
                             "--near-speed-widening maybe"}) {
    expectCleanFailure(std::string("bench wake ") + option + " --csv " + bad.file("x.csv"), bad, {});
  }
  expectCleanFailure("bench wake --csv " + bad.file("x.txt"), bad, {});
}

TEST(BenchCli, WaterBenchmarkWritesItsTableAndRefusesBadSizes) {
  ScratchDir dir;
  const std::string csv = dir.file("water.csv");
  ProcessResult r = runTidepool(
      "bench water --validate --resolutions 48x32 --samples 2 --repeats 1 --frame 3 --csv " + csv + " --plot ''", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("view,width,height,mode,refraction_ms,", 0), 0u) << table.header;
  EXPECT_EQ(table.rows, 3 * 2);  // three views, two modes
  ScratchDir bad;
  for (const char* size : {"48", "48x", "0x32", "48x32x2", "5000x10"}) {
    const std::string error =
        expectCleanFailure(std::string("bench water --resolutions ") + size + " --csv " + bad.file("x.csv"), bad, {});
    EXPECT_NE(error.find(size), std::string::npos) << error;
  }
}

// Two samplings times two sample counts: four rows; the glossy table, three
// samplings times two counts times the 64-wide map's 3 levels. Bad widths,
// sample counts and paths: one clean line, nothing written.
TEST(BenchCli, IblBenchmarkWritesItsTableAndRefusesBadInput) {
  ScratchDir dir;
  const std::string csv = dir.file("ibl.csv"), glossyCsv = dir.file("glossy.csv");
  ProcessResult r =
      runTidepool("bench ibl --validate --width 64 --samples 16,64 --rotations 2 --repeats 1 --csv " + csv +
                      " --plot '' --glossy-samples 16,64 --glossy-csv " + glossyCsv + " --glossy-plot ''",
                  dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("validation: 0 warnings, 0 errors"), std::string::npos) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("sampling,samples,sh_ms,cdf_ms,rms_error,", 0), 0u) << table.header;
  EXPECT_EQ(table.rows, 2 * 2);
  const CsvShape glossy = csvShape(glossyCsv);
  EXPECT_EQ(glossy.header.rfind("sampling,samples,level,exponent,prefilter_ms,rms_error,worst_error,", 0), 0u)
      << glossy.header;
  EXPECT_EQ(glossy.rows, 3 * 2 * 3);
  ScratchDir bad;
  for (const char* width : {"15", "17", "9000"}) {
    const std::string error =
        expectCleanFailure(std::string("bench ibl --width ") + width + " --csv " + bad.file("x.csv"), bad, {});
    EXPECT_NE(error.find(width), std::string::npos) << error;
  }
  expectCleanFailure("bench ibl --samples 0 --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench ibl --csv /dev/null/x.csv", bad, {});
  expectCleanFailure("bench ibl --glossy-samples 1 --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench ibl --csv " + bad.file("x.csv") + " --glossy-csv /dev/null/g.csv", bad, {});
}

// The raster against the path-traced truth, per scene and region.
TEST(BenchCli, TruthBenchmarkWritesItsTableAndRefusesBadInput) {
  ScratchDir dir;
  const std::string csv = dir.file("truth.csv");
  const std::string low = std::string(TIDEPOOL_SOURCE_DIR) + "/scenes/low_sun.json";
  ProcessResult r = runTidepool("bench truth --validate --size 16x9 --samples 2 --raster-samples 1 --scenes default," +
                                    low + " --csv " + csv + " --plot ''",
                                dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const CsvShape table = csvShape(csv);
  EXPECT_EQ(table.header.rfind("scene,raster_s,truth_s,truth_noise,rmse,max_error,rmse_sky,pixels_sky,", 0), 0u)
      << table.header;
  EXPECT_EQ(table.rows, 2);
  ScratchDir bad;
  expectCleanFailure("bench truth --scenes nowhere.json --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench truth --samples 0 --csv " + bad.file("x.csv"), bad, {});
  expectCleanFailure("bench truth --size 4x4 --csv " + bad.file("x.csv"), bad, {});
}

}  // namespace tp::test
