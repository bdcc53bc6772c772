#include "document/pin_set.h"

#include "common/input_error.h"
#include "document/scene_document.h"
#include "scene/pinned_runs.h"

#include <algorithm>
#include <array>
#include <exception>

namespace chaplygin::ui {

namespace {
constexpr int kPinFreeSamples = 2; // the pins' plots and trails show the controlled motion only
} // namespace

PinSet::PinSet(SceneDocument* document) : QObject(document), m_document(document) {}

void PinSet::check(SceneDocument& document, const Scene& scene) {
    for (std::size_t i = 0; i < scene.pins.size(); ++i) {
        try {
            Scene s = sceneOf(scene.pins[i]);
            Solution::compute(s, document.pathFor(s.path));
        } catch (const InputError& e) {
            throw InputError("scene file /pins/" + std::to_string(i),
                             "the pinned run does not solve: " + std::string(e.what()));
        }
    }
}

void PinSet::sync() {
    const std::vector<PinnedRun>& pins = m_document->scene().pins;
    bool same = pins.size() == m_runs.size();
    for (std::size_t i = 0; same && i < pins.size(); ++i)
        same = pins[i] == m_runs[i].pin;
    if (same)
        return;
    std::vector<Run> runs;
    for (const PinnedRun& pin : pins) {
        // a pin solved before keeps its solution (pins are added and cleared, never edited)
        auto old =
            std::find_if(m_runs.begin(), m_runs.end(), [&](const Run& r) { return r.pin == pin; });
        if (old != m_runs.end()) {
            runs.push_back(*old);
            continue;
        }
        Run run;
        run.pin = pin;
        try {
            Scene s = sceneOf(pin);
            run.solution =
                std::make_shared<const Solution>(Solution::compute(s, m_document->pathFor(s.path)));
            run.series = collectSeries(*run.solution, kPinFreeSamples);
        } catch (const std::exception& e) {
            run.error = QString::fromStdString(e.what());
        }
        runs.push_back(std::move(run));
    }
    m_runs = std::move(runs);
}

int PinSet::count() {
    sync();
    return int(m_runs.size());
}

const PinSet::Run& PinSet::run(int index) {
    sync();
    return m_runs.at(std::size_t(index));
}

QString PinSet::label(int index) {
    const Run& r = run(index);
    QString text = QString::fromStdString(pinLabel(r.pin, m_document->scene()));
    return r.error.isEmpty() ? text : text + tr(" (does not solve)");
}

QColor PinSet::color(int index) {
    // the plots' palette after the controlled blue and the free red
    static const std::array<QColor, 5> colors{QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                                              QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                              QColor(0xe3, 0x77, 0xc2)};
    return colors[std::size_t(index) % colors.size()];
}

} // namespace chaplygin::ui
