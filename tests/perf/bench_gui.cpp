// chaplygin-bench: the GUI's recompute and animation-frame costs, measured on the real widgets
// under the offscreen platform.
#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "common/memory_reuse.h"
#include "document/plot_series.h"
#include "document/scene_document.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "shell/main_window.h"
#include "shell/markdown_browser.h"
#include "shell/playback.h"

#include <QApplication>
#include <QTextBrowser>
#include <qcustomplot.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>

namespace {

using namespace chaplygin;
using namespace chaplygin::ui;

// sinusoid preset; change b; recompute (path reused), gather the series and hand them to the
// four plots (their repaint is queued to the next frame)
void BM_RecomputeOnParameterChange(benchmark::State& state) {
    SceneDocument document;
    PlotsPanel plots(&document);
    Scene scene = presetScene("sinusoid");
    if (state.range(0) == 1) {
        // a freehand path: 200 points on a wobbly spiral, smooth corners
        scene.path = PathSource{};
        scene.path.kind = PathKind::Polyline;
        scene.path.corners = CornerMode::Smooth;
        for (int i = 0; i < 200; ++i) {
            double u = 0.05 * i, r = 1 + 0.3 * u + 0.05 * std::sin(7.0 * u);
            scene.path.points.emplace_back(r * std::cos(u), r * std::sin(u));
        }
    }
    document.setSceneNow(scene);
    double b = 1.0;
    for (auto _ : state) {
        b = b > 1.5 ? 1.0 : b + 0.01;
        scene.system.params["b"] = b;
        document.setSceneNow(scene);
        benchmark::DoNotOptimize(document.series().psi.data());
    }
    if (!document.error().isEmpty())
        state.SkipWithError(document.error().toStdString().c_str());
}
// 0: the sinusoid preset (the target); 1: a 200-point drawn path
BENCHMARK(BM_RecomputeOnParameterChange)
    ->ArgName("drawn")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);

// a typed path edited: every iteration a new expression, so the path is tabulated again
void BM_RecomputeOnPathChange(benchmark::State& state) {
    SceneDocument document;
    PlotsPanel plots(&document);
    Scene scene = presetScene("sinusoid");
    document.setSceneNow(scene);
    long k = 0;
    for (auto _ : state) {
        ++k;
        scene.path.y = "-sin(x) + " + std::to_string(0.001 * (k % 100000)) + "*x";
        document.setSceneNow(scene);
        benchmark::DoNotOptimize(document.series().psi.data());
    }
    if (!document.error().isEmpty())
        state.SkipWithError(document.error().toStdString().c_str());
}
BENCHMARK(BM_RecomputeOnPathChange)->Unit(benchmark::kMillisecond);

// the breakdown of a parameter change: solve only, gather the series only, draw the plots only
void BM_StageSolve(benchmark::State& state) {
    Scene scene = presetScene("sinusoid");
    Solution base = Solution::compute(scene);
    for (auto _ : state) {
        Solution s = Solution::compute(scene, base.path());
        benchmark::DoNotOptimize(s.duration());
    }
}
BENCHMARK(BM_StageSolve)->Unit(benchmark::kMillisecond);

void BM_StageCollectSeries(benchmark::State& state) {
    Solution s = Solution::compute(presetScene("sinusoid"));
    for (auto _ : state)
        benchmark::DoNotOptimize(collectSeries(s, SceneDocument::kFreeSamples).psi.data());
}
BENCHMARK(BM_StageCollectSeries)->Unit(benchmark::kMillisecond);

void BM_StageDrawPlots(benchmark::State& state) {
    SceneDocument document;
    PlotsPanel plots(&document);
    document.setSceneNow(presetScene("sinusoid"));
    for (auto _ : state)
        plots.refresh();
}
BENCHMARK(BM_StageDrawPlots)->Unit(benchmark::kMillisecond);

// counts the paint events a widget receives
class PaintCounter : public QObject {
  public:
    int count = 0;
    QEvent::Type type = QEvent::Paint;
    bool eventFilter(QObject*, QEvent* e) override {
        count += e->type() == type ? 1 : 0;
        return false;
    }
};

// the window at a benchmark size: 1280x800 or 1920x1080 (width given)
void sizeWindow(MainWindow& window, long width) {
    window.resize(int(width), width >= 1920 ? 1080 : 800);
}

// Whether the window is shown at device pixel ratio `dpr`; the process has one ratio, set by
// --dpr=N (QT_SCALE_FACTOR), so the variants of another ratio skip with the way to run them.
bool atDevicePixelRatio(benchmark::State& state, const MainWindow& window, long dpr) {
    if (window.devicePixelRatioF() == double(dpr))
        return true;
    const std::string why = "run with --dpr=" + std::to_string(dpr);
    state.SkipWithError(why.c_str());
    for (auto _ : state) {
    }
    return false;
}

// the third (vakonomic) body and every arrow of View > Vectors shown
void showEverything(MainWindow& window) {
    window.canvas()->setShowVakonomic(true);
    Scene scene = window.document()->scene();
    for (int i = 0; i < kVectorKinds; ++i)
        (scene.vectors.*vectorToggle(VectorKind(i))).shown = true;
    window.loadScene(scene);
    window.document()->flush();
}

// one animation frame: advance the clock, repaint the canvas and the four plots
void BM_AnimationFrame(benchmark::State& state) {
    MainWindow window(false);
    sizeWindow(window, state.range(3));
    window.show();
    QCoreApplication::processEvents();
    if (!atDevicePixelRatio(state, window, state.range(5)))
        return;
    if (state.range(4) != 0)
        showEverything(window);
    QCoreApplication::processEvents();
    window.plotsPanel()->replotNow();
    Playback* playback = window.playback();
    playback->setLoop(true);
    playback->setSpeedFactor(double(state.range(0)));    // x1, or x4: every cursor moves by pixels
    window.canvas()->setFollowBody(state.range(1) != 0); // following redraws the cached background
    PaintCounter canvasPaints, plotPaints, layouts;
    layouts.type = QEvent::LayoutRequest;
    window.installEventFilter(&layouts);
    window.canvas()->installEventFilter(&canvasPaints);
    for (int i = 0; i < 4; ++i)
        window.plotsPanel()->plot(i)->installEventFilter(&plotPaints);
    for (auto _ : state) {
        // the clock moves the canvas and the plots' cursors; Qt then paints the dirty widgets
        // in one pass and flushes the window once, as in a real frame
        playback->advance(1.0 / 60);
        if (state.range(2) != 0) // worst case: every plot repaints as a whole, not a strip
            for (int i = 0; i < 4; ++i)
                window.plotsPanel()->plot(i)->update();
        QCoreApplication::processEvents();
    }
    // the canvas repaints every frame; a plot repaints when its cursor moves by a pixel or more
    state.counters["canvas_paints"] =
        benchmark::Counter(canvasPaints.count, benchmark::Counter::kAvgIterations);
    state.counters["plot_paints"] =
        benchmark::Counter(plotPaints.count, benchmark::Counter::kAvgIterations);
    state.counters["layouts"] =
        benchmark::Counter(layouts.count, benchmark::Counter::kAvgIterations);
    state.counters["canvas_w"] = window.canvas()->width();
    state.counters["arrows"] =
        double(window.canvas()->vectorLayer().controlledShapes().arrows.size());
}
// width 1280 (x800) or 1920 (x1080); everything: the vakonomic body and all five vectors shown
BENCHMARK(BM_AnimationFrame)
    ->ArgNames({"speed", "follow", "whole", "width", "everything", "dpr"})
    ->ArgsProduct({{1}, {0}, {0}, {1280, 1920}, {0, 1}, {1}})
    ->Args({4, 0, 0, 1280, 1, 1})
    ->Args({4, 0, 0, 1920, 1, 1})
    ->Args({1, 1, 0, 1280, 1, 1})
    ->Args({1, 1, 0, 1920, 1, 1})
    ->Args({1, 0, 1, 1280, 1, 1})
    ->Args({1, 0, 1, 1920, 1, 1})
    // a 3840 x 2160 frame at 1920 logical width (chaplygin-bench --dpr=2)
    ->Args({1, 0, 0, 1920, 1, 2})
    ->Args({1, 1, 0, 1920, 1, 2})
    ->Iterations(1200) // 20 s of motion at 60 Hz: every run paints the same frames
    ->Unit(benchmark::kMillisecond);

// one zoom step on the canvas (wheel or +/-): the static layer and every trail drawn anew at
// the new scale; zoom 1 at the fitted view, 20 twenty times closer. The steps go in and out by
// 1.1 between two scales, whose body images stay cached; with `seen` 0 every step also moves
// on by 0.1 %, so that each is to a scale never painted before, as a wheel's steps are (the
// bodies' images made anew each time)
void BM_ZoomStep(benchmark::State& state) {
    MainWindow window(false);
    sizeWindow(window, state.range(0));
    window.show();
    QCoreApplication::processEvents();
    if (!atDevicePixelRatio(state, window, state.range(2)))
        return;
    showEverything(window);
    window.canvas()->setTime(5);
    window.canvas()->zoomBy(double(state.range(1)));
    QCoreApplication::processEvents();
    bool in = true;
    const double onwards = state.range(3) != 0 ? 1.0 : 1.001;
    for (auto _ : state) {
        window.canvas()->zoomBy((in ? 1.1 : 1 / 1.1) * onwards);
        in = !in;
        window.canvas()->repaint();
    }
}
BENCHMARK(BM_ZoomStep)
    ->ArgNames({"width", "zoom", "dpr", "seen"})
    ->ArgsProduct({{1280, 1920}, {1, 20}, {1}, {1}})
    ->Args({1920, 1, 2, 1})
    ->Args({1920, 20, 2, 1})
    ->Args({1920, 1, 1, 0})
    ->Args({1920, 1, 2, 0})
    ->Iterations(200)
    ->Unit(benchmark::kMillisecond);

// the breakdown of a frame: the canvas alone, the plots' cursor alone
void BM_StageFrameCanvas(benchmark::State& state) {
    MainWindow window(false);
    sizeWindow(window, state.range(0));
    window.show();
    QCoreApplication::processEvents();
    showEverything(window);
    QCoreApplication::processEvents();
    for (auto _ : state) {
        window.canvas()->setTime(std::fmod(window.canvas()->time() + 1.0 / 60, 17.0));
        window.canvas()->repaint();
    }
}
BENCHMARK(BM_StageFrameCanvas)
    ->ArgName("width")
    ->Arg(1280)
    ->Arg(1920)
    ->Unit(benchmark::kMillisecond);

void BM_StageFramePlots(benchmark::State& state) {
    MainWindow window(false);
    sizeWindow(window, state.range(0));
    window.show();
    QCoreApplication::processEvents();
    showEverything(window);
    QCoreApplication::processEvents();
    window.plotsPanel()->replotNow();
    double t = 0;
    for (auto _ : state) {
        t = std::fmod(t + 1.0 / 60, 17.0);
        window.plotsPanel()->setTime(t);
        for (int i = 0; i < 4; ++i)
            window.plotsPanel()->plot(i)->repaint();
    }
}
BENCHMARK(BM_StageFramePlots)
    ->ArgName("width")
    ->Arg(1280)
    ->Arg(1920)
    ->Unit(benchmark::kMillisecond);

// Opening the numerics notes (the largest help document) in a shown 900 x 700 browser, until
// it is painted: MarkdownBrowser (arg 1) against QTextBrowser's own Markdown loading (arg 0).
void BM_HelpOpenDocument(benchmark::State& state) {
    std::unique_ptr<QTextBrowser> browser;
    if (state.range(0))
        browser = std::make_unique<MarkdownBrowser>();
    else
        browser = std::make_unique<QTextBrowser>();
    browser->setSearchPaths({QStringLiteral(CHAPLYGIN_SOURCE_DIR "/docs")});
    browser->resize(900, 700);
    browser->show();
    QCoreApplication::processEvents();
    const QUrl numerics =
        QUrl::fromLocalFile(QStringLiteral(CHAPLYGIN_SOURCE_DIR "/docs/numerics.md"));
    const QUrl physics =
        QUrl::fromLocalFile(QStringLiteral(CHAPLYGIN_SOURCE_DIR "/docs/physics.md"));
    for (auto _ : state) {
        state.PauseTiming();
        browser->setSource(physics, QTextDocument::MarkdownResource); // another document first
        state.ResumeTiming();
        browser->setSource(numerics, QTextDocument::MarkdownResource);
        browser->viewport()->repaint();
    }
}
BENCHMARK(BM_HelpOpenDocument)
    ->ArgName("markdown_browser")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    chaplygin::keepFreedMemoryForReuse(); // as the program does (app/main.cpp)
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // --dpr=N: every window at device pixel ratio N (the variants with argument dpr:N run)
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--dpr=", 6) == 0) {
            qputenv("QT_SCALE_FACTOR", argv[i] + 6);
            std::copy(argv + i + 1, argv + argc, argv + i);
            --argc;
            break;
        }
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
