// The viewer's logic without a window: edits become requests, results come back from the
// worker, stale work is cancelled, sliders write into the text, files and autosave.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <fstream>
#include <thread>
#include <unistd.h>

#include "app/plant/text_edit.hpp"
#include "app/viewer/state/viewer_state.hpp"
#include "lpy/lpy.hpp"

namespace sprout::viewer {
namespace {
namespace fs = std::filesystem;

const char* kPlant = "n: 3\nangle: 25\naxiom: F\nF -> F[+F]F[-F]F\n";

fs::path tempDir(const std::string& name) {
    fs::path p = fs::path(testing::TempDir()) / ("sprout_viewer_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

// The environment's sliders: each literal number of an `environment:` line, named by what it
// is; an expression of defines has none; a light with no sun gets its sun when moved.
TEST(TextEdit, EnvironmentSlidersMoveTheNumbersOfItsLines) {
    const std::string text = "n: 3\nenvironment: sphere 0 5, 0 R  # the crown\nenvironment: obstacle box -1 2 -1 1 3 1\n"
                             "environment: light 1.5\naxiom: F ?E(0,0)\n";
    auto numbers = environmentNumbers(text);
    std::vector<std::string> labels;
    for (const auto& n : numbers) labels.push_back(n.label + "=" + formatValue(n.value));
    EXPECT_EQ(labels, (std::vector<std::string>{"sphere centre x=0", "sphere centre y=5", "sphere centre z=0",
                                                "obstacle box x0=-1", "obstacle box y0=2", "obstacle box z0=-1",
                                                "obstacle box x1=1", "obstacle box y1=3", "obstacle box z1=1",
                                                "light voxel size=1.5", "light sun azimuth=0", "light sun elevation=90"}));
    EXPECT_EQ(setEnvironmentNumber(text, numbers[1], 6.5),
              "n: 3\nenvironment: sphere 0 6.5, 0 R  # the crown\nenvironment: obstacle box -1 2 -1 1 3 1\n"
              "environment: light 1.5\naxiom: F ?E(0,0)\n");
    EXPECT_EQ(setEnvironmentNumber(text, numbers[11], 40),
              "n: 3\nenvironment: sphere 0 5, 0 R  # the crown\nenvironment: obstacle box -1 2 -1 1 3 1\n"
              "environment: light 1.5 sun 0 40\naxiom: F ?E(0,0)\n");
    auto attraction = environmentNumbers("environment: attraction 300 ellipsoid 0 9 0 5 4 5 influence 6 kill 0.8\n");
    ASSERT_EQ(attraction.size(), 9u);
    EXPECT_EQ(attraction[0].label, "attraction points");
    EXPECT_EQ(attraction[4].label, "attraction ellipsoid radius x");
    EXPECT_EQ(attraction[8].label, "attraction kill");
    auto sun = environmentNumbers("environment: light 1 0.4 sun 30 60\n");
    ASSERT_EQ(sun.size(), 4u);
    EXPECT_EQ(sun[3].label, "light sun elevation");
    EXPECT_EQ(sun[3].value, 60);
}

TEST(TextEdit, SliderValuesGoBackIntoTheText) {
    EXPECT_EQ(setDirective(kPlant, "angle", "30"), "n: 3\nangle: 30\naxiom: F\nF -> F[+F]F[-F]F\n");
    EXPECT_EQ(setDirective("angle: 22 ~ 4\naxiom: F\n", "angle", "30"), "angle: 30 ~ 4\naxiom: F\n");  // jitter kept
    EXPECT_EQ(setDirective("axiom: F\n", "step", "2"), "step: 2\naxiom: F\n");  // inserted before the axiom
    EXPECT_EQ(setDirective("n: 3\r\naxiom: F\r\n", "n", "4"), "n: 4\r\naxiom: F\r\n");
    EXPECT_EQ(setDirective("F -> F\naxiom: F\n", "F", "2"), "F -> F\nF: 2\naxiom: F\n");  // a rule is not a setting
    EXPECT_EQ(setDefine("define: r = 0.5\n#define k 2\naxiom: A(r)\n", "r", "0.75"), "define: r = 0.75\n#define k 2\naxiom: A(r)\n");
    EXPECT_EQ(setDefine("define: r = 0.5\n#define k 2\naxiom: A(r)\n", "k", "3"), "define: r = 0.5\n#define k 3\naxiom: A(r)\n");
    EXPECT_EQ(setDefine("define: rr = 1\n", "r", "3"), "define: rr = 1\n");
    EXPECT_EQ(formatValue(30), "30");
    EXPECT_EQ(formatValue(22.5), "22.5");
    EXPECT_EQ(formatValue(0.123456), "0.123");
    EXPECT_EQ(directiveValue(kPlant, "angle"), "25");
}

// ABOP's notation: sliders write back into the lines as they are written (a caption, δ, n =,
// a constant `R = 1.456`), and the text still reads the same way.
TEST(TextEdit, NotationSlidersWriteBackInPlace) {
    const std::string caption = "n=5, \xCE\xB4=25.7\xC2\xB0\n\xCF\x89: F\np1: F \xE2\x86\x92 F[+F]F\n";
    EXPECT_EQ(setDirective(caption, "angle", "30"), "n=5, \xCE\xB4=30\n\xCF\x89: F\np1: F \xE2\x86\x92 F[+F]F\n");
    EXPECT_EQ(setDirective(caption, "n", "3"), "n=3, \xCE\xB4=25.7\xC2\xB0\n\xCF\x89: F\np1: F \xE2\x86\x92 F[+F]F\n");
    EXPECT_EQ(directiveValue(caption, "angle"), "25.7\xC2\xB0");
    EXPECT_EQ(setDirective("delta = 22.5\nn = 4\naxiom = F\n", "angle", "40"), "delta = 40\nn = 4\naxiom = F\n");
    EXPECT_EQ(setDirective("delta = 22.5\nn = 4\naxiom = F\n", "n", "6"), "delta = 22.5\nn = 6\naxiom = F\n");
    const std::string constant = "R = 1.456\n\xCF\x89: A(1)\nA(s) -> F(s)A(s/R)\n";
    EXPECT_EQ(setDefine(constant, "R", "2"), "R = 2\n\xCF\x89: A(1)\nA(s) -> F(s)A(s/R)\n");
    auto g = parse(setDirective(caption, "angle", "30")).grammar;
    ASSERT_TRUE(g);
    EXPECT_DOUBLE_EQ(g->settings.angle.mean, 30);
    EXPECT_EQ(g->settings.iterations, 5);
}

// An L-Py model's scalars (its INITIALISATION part) are sliders written back in place.
TEST(TextEdit, LpyScalarsAreSlidersWrittenBackInPlace) {
    const std::string text =
        "# scalars = nothing here\nAxiom: A\nderivation length: N\n###### INITIALISATION ######\n"
        "def __initialiseContext__(context):\n"
        "\tscalars = [('N', 'Integer', 3, 1, 20), ('ANGLE', 'Float', 22.5, 0, 90, 2), ('LEAVES', 'Bool', True),\n"
        "\t           ('Shape', 'Category'), ('OLD', 0.25, 0, 1)]\n"
        "\tcontext[\"__scalars__\"] = scalars\n";
    auto scalars = lpyScalars(text);
    ASSERT_EQ(scalars.size(), 5u);
    EXPECT_EQ(scalars[0].name, "N");
    EXPECT_EQ(scalars[0].kind, LpyScalar::Kind::Integer);
    EXPECT_EQ(scalars[0].value, 3);
    EXPECT_EQ(scalars[0].max, 20);
    EXPECT_EQ(scalars[1].kind, LpyScalar::Kind::Float);
    EXPECT_EQ(scalars[1].min, 0);
    EXPECT_EQ(scalars[1].max, 90);
    EXPECT_EQ(scalars[2].kind, LpyScalar::Kind::Bool);
    EXPECT_EQ(scalars[2].value, 1);
    EXPECT_EQ(scalars[3].name, "Shape");
    EXPECT_EQ(scalars[3].kind, LpyScalar::Kind::Category) << "Studio's heading";
    EXPECT_EQ(setLpyScalar(text, scalars[3], 5), text) << "a heading has no value";
    EXPECT_EQ(scalars[4].name, "OLD");
    EXPECT_EQ(scalars[4].kind, LpyScalar::Kind::Float);
    EXPECT_EQ(scalars[4].value, 0.25);
    std::string moved = setLpyScalar(text, scalars[0], 7.4);
    EXPECT_NE(moved.find("('N', 'Integer', 7, 1, 20)"), std::string::npos) << moved;
    moved = setLpyScalar(text, scalars[1], 30);
    EXPECT_NE(moved.find("('ANGLE', 'Float', 30.0, 0, 90, 2)"), std::string::npos) << moved;
    moved = setLpyScalar(text, scalars[2], 0);
    EXPECT_NE(moved.find("('LEAVES', 'Bool', False)"), std::string::npos) << moved;
    EXPECT_EQ(setDirective(text, "derivation length", "5").find("derivation length: 5\n"), text.find("derivation length: N"));
    EXPECT_TRUE(lpyScalars("Axiom: A\n").empty());
}

TEST(ViewerState, EditBecomesAPlant) {
    ViewerState s(tempDir("edit"));
    s.openText(kPlant);
    s.waitForPlant();
    ASSERT_TRUE(s.plant());
    EXPECT_EQ(s.plant()->iterations, 3);
    EXPECT_EQ(s.plant()->geometry->cylinders.size(), 125u);
    s.setText(std::string(kPlant) + "F -> FF\n");  // a warning, still a plant
    s.waitForPlant();
    EXPECT_FALSE(s.latest()->diagnostics.empty());
    EXPECT_TRUE(s.dirty());
}

// The worker says when each result is ready (the window's loop waits for it), and once
// stopped (before the window's GLFW ends) it says nothing more, whatever is posted after.
TEST(Worker, FinishedIsCalledForEachResultAndNeverAfterStop) {
    Worker w;
    std::atomic<int> calls{0};
    w.finished = [&] { ++calls; };
    Request r;
    r.text = kPlant;
    r.generation = 1;
    w.post(r);
    auto result = w.waitForResult(1);
    ASSERT_TRUE(result && result->ok());
    for (int i = 0; i < 500 && calls.load() < 1; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(calls.load(), 1);
    // A long derivation, stopped as it runs: stop() returns once the thread has ended.
    r.text = "n: 40\naxiom: A\nA -> AB\nB -> A\n";
    r.generation = 2;
    w.post(r);
    w.stop();
    const int atStop = calls.load();
    EXPECT_LE(atStop, 2);
    r.generation = 3;
    w.post(r);  // nothing takes it up
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(calls.load(), atStop);
    EXPECT_FALSE(w.busy());
    w.stop();  // again: nothing to do
}

// A worker stopped as it starts, or as it goes back to waiting, stops. stop() set its quit
// flag without the lock: a worker between its wait's check and its sleep missed the wake, and
// stop() waited for it for ever (a viewer test hung so under TSan).
TEST(Worker, StopsWhenStoppedAsItGoesToWait) {
    // Two at a time, 20,000 in all (a second or two): with the old stop() about one run in
    // ten hung here.
    auto stopMany = [] {
        Request r;
        r.text = "axiom: F\n";
        for (int i = 0; i < 10000; ++i) {
            Worker w;
            if (i % 2) r.generation = 1, w.post(r);
            w.stop();
        }
    };
    auto one = std::async(std::launch::async, stopMany), other = std::async(std::launch::async, stopMany);
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    if (one.wait_until(until) != std::future_status::ready || other.wait_until(until) != std::future_status::ready) {
        ADD_FAILURE() << "stop() waits for ever: the worker missed its wake";
        std::fflush(stdout);
        std::_Exit(1);  // the stuck thread cannot be joined
    }
}

TEST(ViewerState, TheTitleNamesTheFileOrThePreset) {
    ViewerState s(tempDir("title"));
    EXPECT_EQ(s.title(), "untitled");
    s.openText("axiom: F\n", {}, "fern");
    EXPECT_EQ(s.title(), "fern (preset)");
    s.openText("axiom: F\n", "/tmp/some/plant.lsys");
    EXPECT_EQ(s.title(), "plant.lsys");
    s.openText("axiom: F\n");  // a restored text
    EXPECT_EQ(s.title(), "untitled");
}

TEST(ViewerState, ErrorsKeepTheLastGoodPlant) {
    ViewerState s(tempDir("errors"));
    s.openText(kPlant);
    s.waitForPlant();
    auto good = s.plant();
    s.setText("n: 3\naxiom: F\nF -> F(sine(1))\n");
    s.waitForPlant();
    EXPECT_EQ(s.plant(), good);  // still on screen
    ASSERT_FALSE(s.latest()->grammar);
    ASSERT_EQ(s.latest()->diagnostics.size(), 1u);
    EXPECT_EQ(s.latest()->diagnostics[0].line, 3);
    EXPECT_EQ(s.latest()->diagnostics[0].col, 8);
}

TEST(ViewerState, SlidersRoundTripThroughTheText) {
    ViewerState s(tempDir("sliders"));
    s.openText("define: r = 0.5\nn: 2\nangle: 25\naxiom: A(1)\nA(x) -> F(x)[+A(x*r)][-A(x*r)]\n");
    s.waitForPlant();
    s.setDirectiveValue("angle", 40);
    s.setDefineValue("r", 0.7);
    s.setIterations(4);
    s.waitForPlant();
    EXPECT_EQ(s.text(), "define: r = 0.7\nn: 4\nangle: 40\naxiom: A(1)\nA(x) -> F(x)[+A(x*r)][-A(x*r)]\n");
    ASSERT_TRUE(s.plant());
    EXPECT_DOUBLE_EQ(s.plant()->grammar->settings.angle.mean, 40);
    EXPECT_DOUBLE_EQ(s.plant()->grammar->defines.at("r"), 0.7);
    EXPECT_EQ(s.plant()->iterations, 4);
}

TEST(ViewerState, NewSpecimenChangesTheSeedInTheText) {
    ViewerState s(tempDir("seed"));
    s.openText("seed: 1\nn: 3\naxiom: F\nF -> F[+F] : 0.5\nF -> F[-F] : 0.5\n");
    s.waitForPlant();
    auto first = s.plant();
    s.newSpecimen();
    s.waitForPlant();
    EXPECT_NE(s.plant()->seed, first->seed);
    EXPECT_NE(directiveValue(s.text(), "seed"), "1");
}

TEST(ViewerState, SteppingThroughIterations) {
    ViewerState s(tempDir("steps"));
    s.openText(kPlant);
    s.waitForPlant();
    s.setDisplayStep(1);
    s.waitForPlant();
    EXPECT_EQ(s.plant()->displayStep, 1);
    EXPECT_EQ(s.plant()->geometry->cylinders.size(), 5u);
    s.stepBy(1);
    s.waitForPlant();
    EXPECT_EQ(s.plant()->geometry->cylinders.size(), 25u);
    s.setDisplayStep(99);  // clamped to n
    s.waitForPlant();
    EXPECT_EQ(s.plant()->displayStep, 3);
    // Playing from the end restarts at step 0 and advances one step per period.
    s.stepsPerSecond = 100;
    s.setPlaying(true);
    s.waitForPlant();
    EXPECT_EQ(s.plant()->displayStep, 0);
    s.tick(0.02);
    s.waitForPlant();
    EXPECT_EQ(s.plant()->displayStep, 1);
}

TEST(ViewerState, StaleWorkIsCancelled) {
    ViewerState s(tempDir("cancel"));
    // A 33 M-module derivation, then an edit: the new plant arrives long before the big one
    // could have finished, and the big one is dropped.
    s.openText("n: 22\naxiom: A(1)\nA(x) -> F(x)[+A(x*0.7)][-A(x*0.7)]\n");
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    auto t0 = std::chrono::steady_clock::now();
    s.setText(kPlant);
    s.waitForPlant();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_TRUE(s.plant());
    EXPECT_EQ(s.plant()->iterations, 3);
    EXPECT_LT(ms, 2000);  // generous: only says the big derivation did not run to its end
}

TEST(ViewerState, SizeCapIsAMessageNotACrash) {
    ViewerState s(tempDir("cap"));
    s.openText("n: 40\naxiom: F\nF -> FFFFFFFFFF\n");
    s.waitForPlant();
    EXPECT_FALSE(s.plant());
    // Said at the line that sets n (issue 39), where the user lowers it.
    ASSERT_EQ(s.latest()->diagnostics.size(), 1u);
    EXPECT_EQ(s.latest()->diagnostics[0].line, 1);
    EXPECT_EQ(s.latest()->diagnostics[0].severity, Severity::Error);
    EXPECT_NE(s.latest()->diagnostics[0].message.find("would produce"), std::string::npos) << s.latest()->diagnostics[0].message;
}

TEST(ViewerState, SaveOpenAndReloadWhenChangedOnDisk) {
    fs::path dir = tempDir("files");
    ViewerState s(dir / "state");
    s.openText(kPlant);
    std::string error;
    ASSERT_TRUE(s.saveAs(dir / "plant.lsys", error)) << error;
    EXPECT_FALSE(s.dirty());
    // Another editor changes the file: the viewer follows.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    { std::ofstream(dir / "plant.lsys") << "n: 2\naxiom: F\nF -> FF\n"; }
    fs::last_write_time(dir / "plant.lsys", fs::file_time_type::clock::now() + std::chrono::seconds(2));
    EXPECT_TRUE(s.reloadIfChangedOnDisk());
    EXPECT_EQ(s.text(), "n: 2\naxiom: F\nF -> FF\n");
    // A failed save keeps the old file and says why.
    EXPECT_FALSE(s.saveAs(dir / "no" / "such" / "dir.lsys", error));
    EXPECT_NE(error.find("could not save"), std::string::npos);
    ViewerState t(dir / "state2");
    ASSERT_TRUE(t.open(dir / "plant.lsys", error));
    EXPECT_EQ(t.text(), "n: 2\naxiom: F\nF -> FF\n");
    EXPECT_FALSE(t.open(dir / "missing.lsys", error));
}

TEST(ViewerState, AutosaveIsOfferedBackAfterACrash) {
    fs::path dir = tempDir("autosave");
    {
        ViewerState s(dir);
        s.openText(kPlant);
        s.setText("n: 4\naxiom: F\nF -> F+F\n");  // an edit, never saved
        s.autosave(true);
        // No markCleanExit(): the process "crashed".
    }
    ViewerState again(dir);
    again.openText(kPlant);
    again.autosave(true);  // the new session's first autosave must not lose the old text
    auto text = again.recoverable();
    ASSERT_TRUE(text);
    EXPECT_EQ(*text, "n: 4\naxiom: F\nF -> F+F\n");
    again.markCleanExit();
    ViewerState clean(dir);
    clean.openText(kPlant);
    EXPECT_FALSE(clean.recoverable());  // a clean exit leaves nothing to recover
}

// The autosave of a frame is written on a thread of its own (its fsyncs are not the frame's);
// a forced one waits for it and writes the text of the moment.
TEST(ViewerState, AutosaveIsWrittenBesideTheFrames) {
    fs::path dir = tempDir("autosave_thread");
    ViewerState s(dir);
    s.openText(kPlant);
    s.setText("n: 1\naxiom: F\nF -> FF\n");
    s.autosave();
    auto onDisk = [&] {
        std::ifstream in(dir / "autosave.lsys", std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (int i = 0; i < 500 && onDisk() != "n: 1\naxiom: F\nF -> FF\n"; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(onDisk(), "n: 1\naxiom: F\nF -> FF\n");
    s.setText("n: 2\naxiom: F\nF -> FF\n");
    s.autosave();  // within 2 s of the last: not yet
    s.setText("n: 3\naxiom: F\nF -> FF\n");
    s.autosave(true);
    EXPECT_EQ(onDisk(), "n: 3\naxiom: F\nF -> FF\n");
}

TEST(ViewerState, AtomicSaveReplacesWholeFiles) {
    fs::path dir = tempDir("atomic");
    std::string error;
    ASSERT_TRUE(saveTextAtomically(dir / "a.lsys", "first", error));
    ASSERT_TRUE(saveTextAtomically(dir / "a.lsys", "second", error));
    std::ifstream in(dir / "a.lsys");
    std::string got((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(got, "second");
    // The temporary has a unique name: nothing is left, and a file of someone else's named
    // like the old fixed temporary is neither overwritten nor renamed away.
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename(), "a.lsys");
    std::ofstream(dir / "a.lsys.saving") << "not ours";
    ASSERT_TRUE(saveTextAtomically(dir / "a.lsys", "third", error)) << error;
    std::ifstream again(dir / "a.lsys"), theirs(dir / "a.lsys.saving");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), "third");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(theirs), {}), "not ours");
    // A symlinked grammar: the file it names is saved, the link stays.
    fs::create_directories(dir / "repo");
    fs::create_symlink("repo/real.lsys", dir / "link.lsys");
    ASSERT_TRUE(saveTextAtomically(dir / "link.lsys", "linked", error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir / "link.lsys"));
    std::ifstream real(dir / "repo" / "real.lsys");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(real), {}), "linked");
    // (A save that fails part way keeps the old file: Files.AFullDiskKeepsTheOldFile.)
    // A path in a folder that does not exist: a message, nothing written.
    error.clear();
    EXPECT_FALSE(saveTextAtomically(dir / "missing" / "b.lsys", "x", error));
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;
}

}  // namespace
}  // namespace sprout::viewer

namespace sprout::viewer {
namespace {

TEST(ViewerState, SmoothGrowthDrawsTheNewStepPartlyGrown) {
    ViewerState s(tempDir("grow"));
    s.openText("n: 3\nangle: 25\nwidth: 0.1\naxiom: F\nF -> F[+F]F[-F]F\n");
    s.waitForPlant();
    const float fullHeight = s.plant()->geometry->bounds.max.y;
    s.stepsPerSecond = 1;
    s.setPlaying(true);  // from the end: back to step 0, growing
    s.waitForPlant();
    s.tick(0.1);
    s.waitForPlant();
    s.tick(1.0);  // past the period: step 1, its new segments at length 0
    s.waitForPlant();
    EXPECT_EQ(s.plant()->displayStep, 1);
    s.tick(0.5);  // half way through step 1
    s.waitForPlant();
    ASSERT_EQ(s.plant()->displayStep, 1);
    EXPECT_NEAR(s.plant()->growFraction, 0.5f, 0.01f);
    const auto& g = *s.plant()->geometry;
    // F -> F[+F]F[-F]F: the old F keeps its length 1 (it is the first F of the successor),
    // the two other trunk segments are new and half grown: 1 + 0.5 + 0.5.
    EXPECT_NEAR(g.bounds.max.y, 2.0f, 1e-4);
    EXPECT_LT(g.bounds.max.y, fullHeight);
    int growing = 0;
    for (const auto& c : g.cylinders) growing += c.step == 1;
    EXPECT_EQ(growing, 4);
}

}  // namespace
}  // namespace sprout::viewer

namespace sprout::viewer {
namespace {

TEST(ViewerState, IteratedFunctionSystemsAndForestsOpenInTheSameEditor) {
    ViewerState s(tempDir("ifs"));
    s.openText("0 0 0 0.16 0 0 0.01\n0.85 0.04 -0.04 0.85 0 1.6 0.85\n0.2 -0.26 0.23 0.22 0 1.6 0.07\n"
               "-0.15 0.28 0.26 0.24 0 0.44 0.07\npoints: 100000\n");
    s.waitForPlant();
    ASSERT_TRUE(s.plant());
    ASSERT_TRUE(s.plant()->image);
    EXPECT_EQ(s.plant()->image->size(), std::size_t(s.plant()->imageWidth) * std::size_t(s.plant()->imageHeight) * 4);
    s.worker().speciesSource = [](const std::string& name) -> std::optional<std::string> {
        if (name == "t") return std::string("n: 2\naxiom: F\nF -> F[+F]F\n");
        return std::nullopt;
    };
    s.setText("scene: forest\ngrid: 2 2\nspecies: t 1\n");
    s.waitForPlant();
    ASSERT_TRUE(s.plant()->geometry);
    EXPECT_EQ(s.plant()->geometry->cylinders.size(), 4u * 9u);
    s.setText("scene: forest\ngrid: 2 2\nspecies: oak 1\n");
    s.waitForPlant();
    EXPECT_EQ(s.latest()->message, "no preset or file named 'oak'");
}


// A PNG as Sprout writes one, reduced to what the viewer reads: a tEXt chunk "lsys".
void writePngCarrying(const fs::path& path, const std::string& text) {
    std::string png("\x89PNG\r\n\x1a\n", 8);
    auto chunk = [&](const std::string& type, const std::string& data) {
        const std::uint32_t n = std::uint32_t(data.size());
        for (int s = 24; s >= 0; s -= 8) png += char((n >> s) & 0xFF);
        png += type + data + std::string(4, '\0');  // the reader checks no CRC
    };
    chunk("tEXt", std::string("lsys") + '\0' + text);
    chunk("IEND", "");
    std::ofstream(path, std::ios::binary) << png;
}

TEST(Trust, ImportsAreListedWithTheirLines) {
    auto imports = pythonImports("import random, os.path as p\n# import no\nfrom math import *\n  import numpy as np  # a comment\n"
                                 "x = 'import nothing'\nfrom . import here\n");
    std::vector<std::string> seen;
    for (const auto& i : imports) seen.push_back(std::to_string(i.line) + ":" + i.module);
    EXPECT_EQ(seen, (std::vector<std::string>{"1:random", "1:os.path", "3:math", "4:numpy", "6:."}));
}

TEST(Trust, AnswersAreKeptByTheTextsHash) {
    const fs::path dir = tempDir("trust_store");
    TrustStore store(dir / "config" / "trusted-models");
    std::string error;
    EXPECT_EQ(store.answer("a"), TrustAnswer::None);
    ASSERT_TRUE(store.remember("a", TrustAnswer::Trusted, error)) << error;
    ASSERT_TRUE(store.remember("b", TrustAnswer::Refused, error)) << error;
    EXPECT_EQ(TrustStore(store.file()).answer("a"), TrustAnswer::Trusted);
    EXPECT_EQ(TrustStore(store.file()).answer("b"), TrustAnswer::Refused);
    EXPECT_EQ(TrustStore(store.file()).answer("a "), TrustAnswer::None);  // another text
    ASSERT_TRUE(store.remember("b", TrustAnswer::Trusted, error));  // a changed mind replaces the answer
    EXPECT_EQ(store.answer("b"), TrustAnswer::Trusted);
    std::ifstream in(store.file());
    const std::string kept((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(std::count(kept.begin(), kept.end(), '\n'), 3) << kept;  // a comment and two answers
    EXPECT_EQ(kept.find("\na\n"), std::string::npos) << "hashes are kept, never texts";
}

// Trust before code runs: a PNG carrying an L-Py model whose preamble writes a file. Opened
// without trust, the file is not written; trusted, it is; the answer is remembered.
TEST(Trust, AModelFromOutsideRunsItsPythonOnlyOnceTrusted) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = tempDir("trust");
    const fs::path marker = dir / "written-by-the-model";
    const std::string model = "import os\nopen('" + marker.string() + "', 'w').write('ran')\n"
                              "Axiom: F\nderivation length: 2\nproduction:\nF --> F F\nendlsystem\n";
    const fs::path png = dir / "plant.png";
    writePngCarrying(png, model);
    const fs::path trustFile = dir / "config" / "trusted-models";
    std::string error;
    {
        ViewerState s(dir / "state", trustFile);
        ASSERT_TRUE(s.open(png, error)) << error;
        EXPECT_EQ(s.kind(), FileKind::Lpy);
        EXPECT_TRUE(s.pythonQuestion());
        ASSERT_EQ(s.imports().size(), 1u);
        EXPECT_EQ(s.imports()[0].module, "os");
        s.waitForPlant();
        EXPECT_FALSE(fs::exists(marker)) << "the model's Python ran without trust";
        ASSERT_TRUE(s.latest());
        EXPECT_NE(s.latest()->message.find("trust"), std::string::npos) << s.latest()->message;
        EXPECT_FALSE(s.latest()->ok());
        s.answerTrust(false);
        s.waitForPlant();
        EXPECT_FALSE(fs::exists(marker));
        EXPECT_TRUE(s.pythonBlocked());
        EXPECT_FALSE(s.pythonQuestion());
    }
    {
        ViewerState s(dir / "state", trustFile);  // reopened: the refusal is remembered
        ASSERT_TRUE(s.open(png, error)) << error;
        EXPECT_FALSE(s.pythonQuestion());
        EXPECT_TRUE(s.pythonBlocked());
        s.waitForPlant();
        EXPECT_FALSE(fs::exists(marker));
        s.answerTrust(true);  // the bar's "Trust and run"
        s.waitForPlant();
        EXPECT_TRUE(fs::exists(marker)) << "trusted, the model runs";
        ASSERT_TRUE(s.plant());
        EXPECT_EQ(s.plant()->geometry->cylinders.size(), 4u);  // F F F F
        EXPECT_EQ(s.plant()->iterations, 2);
        s.setDisplayStep(1);  // stepping draws the kept steps, no second run
        fs::remove(marker);
        s.waitForPlant();
        EXPECT_EQ(s.plant()->geometry->cylinders.size(), 2u);
        EXPECT_FALSE(fs::exists(marker));
    }
    {
        ViewerState s(dir / "state", trustFile);  // trusted once: opens and runs
        ASSERT_TRUE(s.open(png, error)) << error;
        EXPECT_FALSE(s.pythonBlocked());
        s.waitForPlant();
        EXPECT_TRUE(fs::exists(marker));
    }
    fs::remove(marker);
    writePngCarrying(png, model + "# changed\n");
    {
        ViewerState s(dir / "state", trustFile);  // another text is asked about again
        ASSERT_TRUE(s.open(png, error)) << error;
        EXPECT_TRUE(s.pythonQuestion());
        s.waitForPlant();
        EXPECT_FALSE(fs::exists(marker));
        // Recovered text is from outside too.
        s.openText("n: 1\naxiom: F\n", {}, "koch");
        EXPECT_FALSE(s.pythonBlocked());  // a preset: Sprout's own
        s.setText(model);                 // typed (or pasted) by the user: runs
        EXPECT_FALSE(s.pythonBlocked());
        s.waitForPlant();
        EXPECT_TRUE(fs::exists(marker));
    }
}

}  // namespace
}  // namespace sprout::viewer
