// The figure set: each figure's PNG has the report size and the plot's colours, and each
// figure's CSV repeats the run's data (fitness.csv) or a direct simulation (gait, body, path).
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "ga/genome.h"
#include "ga/genome_eval.h"
#include "motor/controller.h"
#include "motor/leg_targets.h"
#include "record/run_record.h"
#include "render/gl_context.h"
#include "render/png_io.h"
#include "report/csv.h"
#include "report/figure_data.h"
#include "report/figures.h"
#include "report/gnuplot.h"
#include "sim/evaluate.h"
#include "test_util.h"
#include "util/error.h"
#include "util/folder_path.h"
#include "util/json_file.h"
#include "util/output.h"

namespace hexgait {
namespace {
namespace fs = std::filesystem;

constexpr double kTime = 140;  // a little over two gait cycles: short, and enough to walk
constexpr int kGaitCycles = 2;

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A temporary folder removed at the end of the test suite.
std::string MakeTempDir() {
  std::string pattern = (fs::temp_directory_path() / "hexgait_figures_test.XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

// A small evolve folder written by hand: three generations, and run.json's baseline.
void WriteRun(const std::string& dir) {
  fs::create_directories(dir);
  WriteText(dir + "/fitness.csv",
            "generation,best,mean,worst\n0,1.25,0.5,-0.125\n1,2.5,1.75,1\n2,3.0000000000000004,"
            "2.25,1.5\n");
  RunRecord run;
  run.seed = 7;
  run.population = 4;
  run.generations = 2;
  run.integrator = "euler";
  run.unoptimized.distance = 0.5;
  WriteText(dir + "/run.json", RunRecordJson(run).dump(2) + "\n");
}

class FiguresTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = MakeTempDir();
    model_ = new CreatureModel(test::DefaultCreature());
    program_ = new MotorProgram(LoadMotorProgramOrDefault("", *model_));
    WriteRun(root_ + "/run");
    // The evolved program: a few genes away from the unoptimized one.
    const auto layout = MakeGenomeLayout(*model_, *program_, false);
    evolved_ = new Genome(layout);
    for (int g = 0; g < layout->num_genes(); g += 7) evolved_->set_gene(g, (g % 5) - 2);
    run_.duration = kTime;
    std::string error;
    has_gl_ = GlContext::Create(&error) != nullptr;
    FiguresOptions options = Options();
    FigurePrograms programs{*model_, *program_, Genome(layout), *evolved_, "test genome", run_};
    manifest_ = new nlohmann::json(MakeFigures(options, programs, [](const std::string&) {}));
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(root_, ec);
    delete manifest_;
    delete evolved_;
    delete program_;
    delete model_;
  }
  static FiguresOptions Options() {
    FiguresOptions options;
    options.run_dir = root_ + "/run";
    options.runs = {root_ + "/run", root_ + "/run"};
    options.bench_dir = std::string(HEXGAIT_SOURCE_DIR "/tests/data/bench_synthetic");
    options.out_dir = root_ + "/figures";
    options.gait_cycles = kGaitCycles;
    options.figure1 = has_gl_;
    return options;
  }
  static std::string Out(const std::string& name) { return root_ + "/figures/" + name; }

  // Direct simulation of a program with the trace the figures use (every 0.1 time units).
  static ProgramTrace Direct(const Genome& genome) {
    return TraceProgram("direct", *model_, *program_, genome, run_, 0.1);
  }

  static std::string root_;
  static CreatureModel* model_;
  static MotorProgram* program_;
  static Genome* evolved_;
  static RunOptions run_;
  static bool has_gl_;
  static nlohmann::json* manifest_;
};

std::string FiguresTest::root_;
CreatureModel* FiguresTest::model_ = nullptr;
MotorProgram* FiguresTest::program_ = nullptr;
Genome* FiguresTest::evolved_ = nullptr;
RunOptions FiguresTest::run_;
bool FiguresTest::has_gl_ = false;
nlohmann::json* FiguresTest::manifest_ = nullptr;

// Pixels within `tolerance` of the colour "#rrggbb" on every channel.
int CountColour(const Image& image, const std::string& hex, int tolerance = 6) {
  const int r = std::stoi(hex.substr(1, 2), nullptr, 16);
  const int g = std::stoi(hex.substr(3, 2), nullptr, 16);
  const int b = std::stoi(hex.substr(5, 2), nullptr, 16);
  int count = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    count += std::abs(image.rgba[i] - r) <= tolerance &&
             std::abs(image.rgba[i + 1] - g) <= tolerance &&
             std::abs(image.rgba[i + 2] - b) <= tolerance;
  }
  return count;
}

void ExpectPlot(const std::string& path, const std::vector<std::string>& colours) {
  ASSERT_TRUE(fs::exists(path)) << path;
  const Image image = ReadPng(path);
  EXPECT_EQ(image.width, kFigureWidth) << path;
  EXPECT_EQ(image.height, kFigureHeight) << path;
  // Mostly white background, and each plot colour on a visible number of pixels.
  EXPECT_GT(CountColour(image, "#ffffff", 0), image.width * image.height / 4) << path;
  for (const std::string& colour : colours) {
    EXPECT_GT(CountColour(image, colour), 200) << path << ": too few pixels of " << colour;
  }
}

TEST_F(FiguresTest, EveryFigureIsAReportSizedPlotInItsColours) {
  const std::string unopt = colours::kUnoptimized, evolved = colours::kEvolved;
  ExpectPlot(Out("fitness.png"), {evolved, colours::kMean, colours::kWorst, colours::kPaper});
  ExpectPlot(Out("fitness_seeds.png"), {evolved, colours::kPaper});
  ExpectPlot(Out("gait.png"), {unopt, evolved, "#d9d9d9"});
  ExpectPlot(Out("body.png"), {unopt, evolved});
  ExpectPlot(Out("path.png"), {unopt, evolved});
  ExpectPlot(Out("accuracy.png"), {colours::kSeries[0], colours::kSeries[1], colours::kSeries[2]});
  ExpectPlot(Out("stability.png"), {colours::kStable, colours::kDiverged});
  for (const char* name :
       {"fitness", "fitness_seeds", "gait", "body", "path", "accuracy", "stability"}) {
    for (const char* ext : {".svg", ".csv", ".gp"}) {
      EXPECT_TRUE(fs::exists(Out(std::string(name) + ext))) << name << ext;
    }
  }
  EXPECT_FALSE(fs::exists(Out(".hexgait-figures.tmp")));
  EXPECT_TRUE(fs::exists(Out(kFiguresMarker)));
}

TEST_F(FiguresTest, Figure1IsTheRenderedCreature) {
  if (!has_gl_) GTEST_SKIP() << "no GL context";
  const Image image = ReadPng(Out("figure1.png"));
  EXPECT_EQ(image.width, kFigureWidth);
  EXPECT_EQ(image.height, kFigureHeight);
  // Not blank: the body's orange and the legs' blue (lit, so only roughly) are both there.
  int orange = 0, blue = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    orange += r > g + 40 && g > b + 20;
    blue += b > r + 40 && b > g + 10;
  }
  EXPECT_GT(orange, 5000);
  EXPECT_GT(blue, 2000);
}

TEST_F(FiguresTest, ManifestListsEveryFigureWithItsFiles) {
  std::vector<std::string> names;
  for (const auto& f : (*manifest_)["figures"]) {
    names.push_back(f["name"]);
    for (const auto& file : f["files"]) EXPECT_TRUE(fs::exists(Out(file))) << file;
    EXPECT_FALSE(f["caption"].get<std::string>().empty());
    if (f["name"] == "gait") {
      EXPECT_NE(f["caption"].get<std::string>().find("for the first 2 gait cycles"),
                std::string::npos)
          << f["caption"];
    }
  }
  std::vector<std::string> expected = {"fitness", "fitness_seeds", "gait",     "body",
                                       "path",    "accuracy",      "stability"};
  if (has_gl_) expected.insert(expected.begin(), "figure1");
  EXPECT_EQ(names, expected);
  EXPECT_TRUE((*manifest_)["skipped"].empty());
  const nlohmann::json on_disk = nlohmann::json::parse(std::ifstream(Out(kFiguresManifest)));
  EXPECT_EQ(on_disk, *manifest_);
}

TEST_F(FiguresTest, FitnessCsvRepeatsTheRunsFitnessCsv) {
  const std::vector<FitnessRow> run = ReadFitnessCsv(root_ + "/run/fitness.csv");
  const CsvTable figure =
      CsvTable::Read(Out("fitness.csv"), {"generation", "best", "mean", "worst", "best_ratio"});
  ASSERT_EQ(figure.rows(), run.size());
  for (size_t g = 0; g < run.size(); ++g) {
    EXPECT_EQ(figure.Number(g, "generation"), run[g].generation);
    EXPECT_EQ(figure.Number(g, "best"), run[g].best);  // bit-exact: %.17g
    EXPECT_EQ(figure.Number(g, "mean"), run[g].mean);
    EXPECT_EQ(figure.Number(g, "worst"), run[g].worst);
    EXPECT_EQ(figure.Number(g, "best_ratio"), run[g].best / 0.5);
  }
  // Two copies of the same run: median, min and max of the best all equal it.
  const CsvTable seeds =
      CsvTable::Read(Out("fitness_seeds.csv"), {"runs", "median_best", "min_best", "max_best"});
  ASSERT_EQ(seeds.rows(), run.size());
  for (size_t g = 0; g < run.size(); ++g) {
    EXPECT_EQ(seeds.Number(g, "runs"), 2);
    EXPECT_EQ(seeds.Number(g, "median_best"), run[g].best);
    EXPECT_EQ(seeds.Number(g, "min_best"), run[g].best);
    EXPECT_EQ(seeds.Number(g, "max_best"), run[g].best);
  }
}

TEST(FigureData, SeedStatisticsAreMedianMinAndMax) {
  std::vector<SeedRun> runs;
  for (double best : {3.0, 1.0, 2.0, 10.0}) {
    runs.push_back({"r", {{0, best, 0, 0}}, 2.0});
  }
  const std::string csv = FitnessSeedsCsv(runs);
  EXPECT_NE(csv.find("\n0,4,1.25,0.5,5,2.5,1,10\n"), std::string::npos) << csv;
  runs[1].rows.push_back({1, 1, 1, 1});
  EXPECT_THROW(FitnessSeedsCsv(runs), InputError);
}

// Foot heights every `every` steps, recorded without TraceRecorder.
struct FootHeights {
  const CreatureModel& model;
  long long every;
  std::vector<double> time;
  std::vector<std::vector<double>> z;  // [sample][leg]
  void OnStep(const SimState& s) {
    if (s.step % every != 0) return;
    time.push_back(s.time);
    z.emplace_back();
    for (const Leg& leg : model.legs) z.back().push_back(s.z[leg.foot]);
  }
};

// Every sample of a direct simulation before the window's end: the foot is below the contact
// height exactly when gait.csv has an interval of that program and leg around the sample.
TEST_F(FiguresTest, GaitCsvContactsMatchADirectSimulation) {
  const CsvTable gait = CsvTable::Read(Out("gait.csv"), {"program", "kind", "leg", "start", "end"});
  const double until = kGaitCycles * program_->cycle_period;
  const auto layout = MakeGenomeLayout(*model_, *program_, false);
  int checked = 0, contacts = 0;
  for (const auto& [name, genome] :
       {std::pair<std::string, Genome>{"unoptimized", Genome(layout)}, {"evolved", *evolved_}}) {
    MotorController controller(*model_, *program_, PerturbedRestLengths(*model_, *program_, genome),
                               run_.dt);
    SimState state = MakeRestState(*model_);
    FootHeights feet{*model_, 40, {}, {}};
    feet.OnStep(state);
    Simulate(*model_, controller, state, run_, feet);
    for (size_t i = 0; i < feet.time.size() && feet.time[i] < until; ++i) {
      for (int leg = 0; leg < 6; ++leg) {
        bool in_interval = false;
        for (size_t r = 0; r < gait.rows(); ++r) {
          in_interval |= gait.Text(r, "program") == name && gait.Text(r, "kind") == "contact" &&
                         gait.Number(r, "leg") == leg &&
                         gait.Number(r, "start") <= feet.time[i] + 1e-6 &&
                         feet.time[i] + 1e-6 < gait.Number(r, "end");
        }
        EXPECT_EQ(in_interval, feet.z[i][leg] < kFootContactHeight)
            << name << " leg " << leg << " t " << feet.time[i];
        ++checked;
        contacts += in_interval;
      }
    }
  }
  EXPECT_GT(checked, 2000);
  EXPECT_GT(contacts, checked / 3);  // the creature stands on its feet most of the time
}

// The grey swing bars are where the program holds the leg in its "swing" position, and they
// follow the metachronal wave: right rear, middle, front, then the left side half a cycle on.
TEST_F(FiguresTest, GaitCsvSwingsFollowTheMotorProgram) {
  const CsvTable gait = CsvTable::Read(Out("gait.csv"), {"program", "kind", "leg", "start", "end"});
  int swing = -1;
  for (int p = 0; p < program_->num_positions(); ++p) {
    if (program_->positions[p].name == "swing") swing = p;
  }
  ASSERT_GE(swing, 0);
  std::map<int, double> first_start;
  int rows = 0;
  for (size_t r = 0; r < gait.rows(); ++r) {
    if (gait.Text(r, "kind") != "swing") continue;
    ++rows;
    EXPECT_EQ(gait.Text(r, "program"), "motor_program");
    const int leg = static_cast<int>(gait.Number(r, "leg"));
    const double mid = 0.5 * (gait.Number(r, "start") + gait.Number(r, "end"));
    EXPECT_EQ(LegPositionsAt(*program_, 6, mid)[leg], swing) << "leg " << leg << " t " << mid;
    if (!first_start.count(leg)) first_start[leg] = gait.Number(r, "start");
  }
  EXPECT_GE(rows, 6 * kGaitCycles - 1);
  // Legs 0-2 are right rear, middle, front; 3-5 the left ones.
  ASSERT_EQ(first_start.size(), 6u);
  EXPECT_LT(first_start[0], first_start[1]);
  EXPECT_LT(first_start[1], first_start[2]);
  EXPECT_NEAR(first_start[3] - first_start[0], program_->mirror_time_offset, 0.11);
}

TEST_F(FiguresTest, BodyAndPathCsvsMatchADirectSimulation) {
  const CsvTable body = CsvTable::Read(
      Out("body.csv"), {"time", "evolved_height", "evolved_pitch_degrees", "evolved_roll_degrees"});
  const CsvTable path = CsvTable::Read(Out("path.csv"), {"time", "evolved_x", "evolved_y"});
  const ProgramTrace direct = Direct(*evolved_);
  const int stride = FiguresOptions().curve_stride;
  ASSERT_EQ(body.rows(), (direct.samples.size() + stride - 1) / stride);
  ASSERT_EQ(path.rows(), body.rows());
  for (size_t r = 0; r < body.rows(); ++r) {
    const TraceSample& s = direct.samples[r * stride];
    EXPECT_NEAR(body.Number(r, "time"), s.time, 1e-4);
    EXPECT_NEAR(body.Number(r, "evolved_height"), s.centre.z(), 1e-6);
    EXPECT_NEAR(body.Number(r, "evolved_pitch_degrees"), s.pitch_degrees, 1e-3);
    EXPECT_NEAR(body.Number(r, "evolved_roll_degrees"), s.roll_degrees, 1e-3);
    EXPECT_NEAR(path.Number(r, "evolved_x"), s.centre.x(), 1e-6);
    EXPECT_NEAR(path.Number(r, "evolved_y"), s.centre.y(), 1e-6);
  }
  // The path's x displacement is the fitness.
  const RunResult result = EvaluateGenome(*model_, *program_, *evolved_, run_);
  EXPECT_NEAR(path.Number(path.rows() - 1, "evolved_x") - path.Number(0, "evolved_x"),
              result.distance, 2e-6);
}

TEST_F(FiguresTest, BenchFiguresKeepStableRowsAndClassifyEveryCell) {
  const std::string bench = std::string(HEXGAIT_SOURCE_DIR "/tests/data/bench_synthetic/");
  const CsvTable in = CsvTable::Read(bench + "accuracy.csv", {"stable", "pos_error_cycle1"});
  const CsvTable out = CsvTable::Read(Out("accuracy.csv"), {"integrator", "pos_error_cycle1"});
  size_t stable = 0;
  for (size_t r = 0; r < in.rows(); ++r) stable += in.Bool(r, "stable");
  EXPECT_EQ(out.rows(), stable);
  const CsvTable map_in = CsvTable::Read(bench + "stability.csv", {"stable"});
  const CsvTable map_out = CsvTable::Read(Out("stability.csv"), {"stable"});
  ASSERT_EQ(map_out.rows(), map_in.rows());
  for (size_t r = 0; r < map_in.rows(); ++r) {
    EXPECT_EQ(map_out.Bool(r, "stable"), map_in.Bool(r, "stable"));
  }
}

// A bench file's names are outside text of any length: a 300-character integrator name once
// overflowed a fixed line buffer, cutting the plotted CSV's row short (and gnuplot failed on it).
TEST_F(FiguresTest, BenchFiguresKeepLongNamesWhole) {
  const std::string bench = root_ + "/long_names_bench";
  fs::create_directories(bench);
  const std::string name(300, 'x');
  WriteText(bench + "/accuracy.csv",
            "integrator,program,dt,stable,pos_error_cycle1,wall_s_per_1000tu\n" + name +
                ",unoptimized,0.01,1,0.02,0.05\n" + name + ",unoptimized,0.005,1,0.01,0.1\n");
  WriteText(bench + "/stability.csv",
            "integrator,stiffness_multiplier,dt,stable,max_energy_ratio\n" + name +
                ",1,0.00125,1,1.01\n" + name + ",1,0.0025,0,7.5\n");
  FiguresOptions options = Options();
  options.bench_dir = bench;
  options.runs.clear();
  options.figure1 = false;
  options.out_dir = root_ + "/long_names_figures";
  options.gait_cycles = 100;  // more than the run (kTime, 2.1 cycles) holds
  const nlohmann::json manifest = MakeFigures(
      options,
      FigurePrograms{*model_, *program_, Genome(MakeGenomeLayout(*model_, *program_, false)),
                     *evolved_, "test genome", run_},
      [](const std::string&) {});
  const CsvTable accuracy =
      CsvTable::Read(options.out_dir + "/accuracy.csv", {"integrator", "wall_s_per_1000tu"});
  ASSERT_EQ(accuracy.rows(), 2u);
  EXPECT_EQ(accuracy.Text(1, "integrator"), name);
  EXPECT_EQ(accuracy.Number(0, "wall_s_per_1000tu"), 0.1);  // sorted by dt
  const CsvTable stability =
      CsvTable::Read(options.out_dir + "/stability.csv", {"integrator", "max_energy_ratio"});
  ASSERT_EQ(stability.rows(), 2u);
  EXPECT_EQ(stability.Text(1, "integrator"), name);
  EXPECT_EQ(stability.Number(1, "max_energy_ratio"), 7.5);
  EXPECT_TRUE(fs::exists(options.out_dir + "/accuracy.png"));
  EXPECT_TRUE(fs::exists(options.out_dir + "/stability.png"));
  // The gait diagram says how much of a cycle it shows when the run ends inside one.
  for (const auto& f : manifest["figures"]) {
    if (f["name"] == "gait") {
      EXPECT_NE(f["caption"].get<std::string>().find("for the first 2.1 gait cycles"),
                std::string::npos)
          << f["caption"];
    }
  }
}

// Helpers for the error cases: one figure set made with `options` must fail.
class FiguresErrorTest : public FiguresTest {
 protected:
  static FigurePrograms Programs() {
    return {*model_,   *program_,     Genome(MakeGenomeLayout(*model_, *program_, false)),
            *evolved_, "test genome", run_};
  }
  static void ExpectFailure(const FiguresOptions& options, const std::string& message) {
    try {
      MakeFigures(options, Programs(), [](const std::string&) {});
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
};

TEST_F(FiguresErrorTest, MissingBenchFilesAreSkippedNotErrors) {
  FiguresOptions options = Options();
  options.bench_dir = root_ + "/no_bench";
  options.runs.clear();
  options.figure1 = false;
  options.out_dir = root_ + "/no_bench_figures";
  const nlohmann::json manifest = MakeFigures(options, Programs(), [](const std::string&) {});
  ASSERT_EQ(manifest["skipped"].size(), 2u);
  EXPECT_EQ(manifest["skipped"][0]["name"], "accuracy");
  EXPECT_NE(manifest["skipped"][0]["reason"].get<std::string>().find("hexgait bench accuracy"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(options.out_dir + "/accuracy.png"));
  EXPECT_TRUE(fs::exists(options.out_dir + "/gait.png"));
}

TEST_F(FiguresErrorTest, BadInputLeavesNoOutput) {
  FiguresOptions options = Options();
  options.figure1 = false;
  options.out_dir = root_ + "/bad";
  options.run_dir = root_ + "/missing_run";
  ExpectFailure(options, "missing_run/run.json");
  EXPECT_FALSE(fs::exists(options.out_dir));

  // A fitness.csv with a broken row names the file and line.
  const std::string broken = root_ + "/broken_run";
  WriteRun(broken);
  WriteText(broken + "/fitness.csv", "generation,best,mean,worst\n0,1,2\n");
  options.run_dir = broken;
  ExpectFailure(options, "fitness.csv line 2: 3 fields, the header has 4");
  EXPECT_FALSE(fs::exists(options.out_dir));

  // A folder not written by hexgait is never replaced.
  const std::string foreign = root_ + "/foreign";
  fs::create_directories(foreign);
  WriteText(foreign + "/notes.txt", "mine");
  options.run_dir = root_ + "/run";
  options.out_dir = foreign;
  ExpectFailure(options, "was not written by hexgait");
  EXPECT_TRUE(fs::exists(foreign + "/notes.txt"));
  for (const auto& entry : fs::directory_iterator(root_)) {
    EXPECT_EQ(entry.path().string().find(".partial."), std::string::npos) << entry.path();
  }
}

TEST_F(FiguresErrorTest, MissingGnuplotIsAClearError) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (root_ + "/empty_path").c_str(), 1);
  FiguresOptions options = Options();
  options.figure1 = false;
  options.out_dir = root_ + "/no_gnuplot";
  // A tool missing from the machine is a SystemError (exit 4), found before any figure's work.
  try {
    MakeFigures(options, Programs(), [](const std::string&) {});
    ADD_FAILURE() << "no error";
  } catch (const SystemError& e) {
    EXPECT_NE(std::string(e.what()).find("gnuplot not found on PATH"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(CheckGnuplotFound(), SystemError);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NO_THROW(CheckGnuplotFound());
  EXPECT_FALSE(fs::exists(options.out_dir));
}

// hexgait's CSVs have no quoting: a name from outside (a gait's file, a group) with a comma, a
// quote or a line break is written so its row keeps its columns and reads back.
TEST(Csv, OutsideTextKeepsItsRowsColumns) {
  const std::string name = "my,gait \"v2\"\r\nfinal.genome";
  const std::string path = ::testing::TempDir() + "/hexgait_csv_text.csv";
  WriteFileAtomically(path,
                      "group,gait,distance\n" + CsvText("a,b") + "," + CsvText(name) + ",1.5\n");
  const CsvTable table = CsvTable::Read(path, {"group", "gait", "distance"});
  ASSERT_EQ(table.rows(), 1u);
  EXPECT_EQ(table.Text(0, "group"), "a_b");
  EXPECT_EQ(table.Text(0, "gait"), "my_gait _v2___final.genome");
  EXPECT_EQ(table.Number(0, "distance"), 1.5);
  std::remove(path.c_str());
}

TEST(NormalFolderPath, OneSpellingForEveryCheckAndWrite) {
  EXPECT_EQ(NormalFolderPath("out/figs/."), "out/figs");
  EXPECT_EQ(NormalFolderPath("out/figs/"), "out/figs");
  EXPECT_EQ(NormalFolderPath("out//./figs"), "out/figs");
  EXPECT_EQ(NormalFolderPath("out/x/../figs"), "out/figs");
  EXPECT_EQ(NormalFolderPath("/"), "/");
  // A name that ends in . or .. gets one of its own (the folder it names).
  EXPECT_EQ(NormalFolderPath("."), std::filesystem::current_path().string());
  EXPECT_EQ(NormalFolderPath("out/.."), std::filesystem::current_path().string());
}

TEST(AtomicDir, AFolderSpelledWithADotIsWrittenWhole) {
  const std::filesystem::path root =
      std::filesystem::temp_directory_path() / ("hexgait_dot_" + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);
  for (int round = 0; round < 2; ++round) {  // new, then replacing its own folder
    AtomicDir dir((root / "figs").string() + "/.", ".hexgait-test", "--out");
    WriteFileAtomically(dir.File("a.txt"), "x" + std::to_string(round));
    dir.Commit();
    EXPECT_EQ(ReadTextFile((root / "figs" / "a.txt").string()), "x" + std::to_string(round));
  }
  std::filesystem::remove_all(root);
}

TEST(AtomicDir, ReplacesItsOwnFolderWhole) {
  const std::string root = MakeTempDir();
  const std::string path = root + "/out";
  {
    AtomicDir dir(path, ".mine", "--out");
    WriteText(dir.File("a.txt"), "1");
    dir.Commit();
  }
  EXPECT_TRUE(fs::exists(path + "/a.txt"));
  {
    AtomicDir dir(path, ".mine", "--out");
    WriteText(dir.File("b.txt"), "2");
    EXPECT_TRUE(fs::exists(path + "/a.txt"));  // the old folder stays until Commit
    dir.Commit();
  }
  EXPECT_FALSE(fs::exists(path + "/a.txt"));
  EXPECT_TRUE(fs::exists(path + "/b.txt"));
  {
    AtomicDir dir(path, ".mine", "--out");
    WriteText(dir.File("c.txt"), "3");
  }  // no Commit: nothing changes, and the temporary folder is gone
  EXPECT_TRUE(fs::exists(path + "/b.txt"));
  EXPECT_FALSE(fs::exists(path + "/c.txt"));
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(root)) ++entries;
  EXPECT_EQ(entries, 1u);
  EXPECT_THROW(AtomicDir(path, ".other", "--out"), InputError);
  EXPECT_THROW(AtomicDir(root + "/missing/out", ".mine", "--out"), InputError);
  fs::remove_all(root);
}

TEST(AtomicDir, ChecksItsParentNotANameBesideIt) {
  // The parent's check once probed OUT.check: a folder of that name, which the user never
  // named, made the write fail with a message about it.
  const std::string root = MakeTempDir();
  const std::string path = root + "/out";
  fs::create_directory(path + ".check");
  {
    AtomicDir dir(path, ".mine", "--out");
    WriteText(dir.File("a.txt"), "1");
    dir.Commit();
  }
  EXPECT_TRUE(fs::exists(path + "/a.txt"));
  try {
    AtomicDir(root + "/missing/out", ".mine", "--out");
    ADD_FAILURE() << "a missing parent was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--out '" + root + "/missing/out': folder '" + root +
                                         "/missing' does not exist"),
              std::string::npos)
        << e.what();
  }
  fs::remove_all(root);
}

TEST(Gnuplot, TextEscapesEnhancedMarkupButQuoteKeepsData) {
  EXPECT_EQ(GnuplotQuote("semi_implicit \"x\"\n"), "\"semi_implicit \\\"x\\\"\\n\"");
  EXPECT_EQ(GnuplotText("semi_implicit^2"), "\"semi\\\\_implicit\\\\^2\"");
}

}  // namespace
}  // namespace hexgait
