#pragma once
#include "document/plot_series.h"
#include "scene/scene.h"
#include "scene/solution.h"

#include <QColor>
#include <QObject>
#include <QString>

#include <memory>
#include <vector>

namespace chaplygin::ui {

class SceneDocument;

/// The solved pinned runs of the open scene ("Pin this run"): each pin of the document's scene
/// solved once (its path from the document's cache) and gathered into plot series. It follows
/// the document's scene lazily: every accessor first brings it up to date, so the canvas and the
/// plots see the same pins whatever order they repaint in. One per document (see of()).
class PinSet : public QObject {
    Q_OBJECT
  public:
    struct Run {
        PinnedRun pin;
        std::shared_ptr<const Solution> solution; ///< null when the pin does not solve
        PlotSeries series;
        QString error; ///< why it does not solve
    };

    /// The pin set of a document (SceneDocument::pins), its child.
    explicit PinSet(SceneDocument* document);

    /// Solves every pin of a scene; throws InputError("scene file /pins/N", ...) for the first
    /// one that does not solve (to vet a file before it replaces the current scene).
    static void check(SceneDocument& document, const Scene& scene);

    int count();
    const Run& run(int index);
    /// What differs from the current scene, e.g. "b = 0.5 m".
    QString label(int index);
    /// The same colour on the canvas and the plots.
    static QColor color(int index);

  private:
    void sync();

    SceneDocument* m_document;
    std::vector<Run> m_runs;
};

} // namespace chaplygin::ui
