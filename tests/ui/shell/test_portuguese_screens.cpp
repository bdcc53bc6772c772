// Portuguese throughout: with the pt_BR catalogues loaded (the program's and Qt's own qtbase), the
// window, every dock, the presets, the gallery, the Methods and Sweep docks, the dialogs with their
// buttons and the help window show no text that is still the English one, and no label or button
// is narrower than its text at 1024x768 and 1920x1080, in either language.
#include "canvas/scene_canvas.h"
#include "common/input_error.h"
#include "gui_test_support.h"
#include "lab/gallery.h"
#include "panels/methods_panel.h"
#include "scene/csv_columns.h"
#include "scene/presets.h"
#include "scene/solution.h"
#include "shell/animation_dialog.h"
#include "shell/help_window.h"
#include "shell/introduction_window.h"
#include "shell/main_window.h"
#include "systems/system.h"
#include "translations.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QTabBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QToolButton>
#include <QTranslator>
#include <QtTest>

#include <qcustomplot.h>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// one text on screen and where it was seen
struct Shown {
    QString text;
    QString where;
};

QString plain(const QString& text) {
    QString t =
        Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
    t.remove(QRegularExpression(QStringLiteral("&(?=\\S)"))); // mnemonics
    return t.simplified();
}

QString describe(const QObject* o) {
    QString path;
    for (; o; o = o->parent()) {
        const QString name = o->objectName().isEmpty()
                                 ? QString::fromLatin1(o->metaObject()->className())
                                 : o->objectName();
        path = path.isEmpty() ? name : name + u'/' + path;
    }
    return path;
}

void add(QList<Shown>& out, const QString& text, const QObject* where) {
    // a document's lines one by one: a note or a readout is checked line by line, a rich text's
    // lines and paragraphs too
    static const QRegularExpression lineBreak(QStringLiteral("[\\n\\x{2029}]|<br ?/?>|</?p[^>]*>"),
                                              QRegularExpression::CaseInsensitiveOption);
    for (const QString& line : text.split(lineBreak)) {
        const QString t = plain(line);
        if (!t.isEmpty())
            out.append({t, describe(where)});
    }
}

void addActions(QList<Shown>& out, const QList<QAction*>& actions, const QObject* where) {
    for (QAction* a : actions) {
        if (a->isSeparator())
            continue;
        add(out, a->text(), where);
        add(out, a->toolTip(), where);
        add(out, a->statusTip(), where);
        if (a->menu())
            add(out, a->menu()->title(), a->menu());
    }
}

// every text a user can read in this widget and its children: labels, buttons, group titles,
// tabs, dock titles, table headers and cells, combo items, menus and actions, tooltips, read-only
// documents, placeholder texts and window titles
QList<Shown> visibleTexts(QWidget* root) {
    QList<Shown> out;
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets) {
        add(out, w->toolTip(), w);
        if (w->isWindow())
            add(out, w->windowTitle(), w);
        addActions(out, w->actions(), w);
        if (auto* l = qobject_cast<QLabel*>(w))
            add(out, l->text(), w);
        else if (auto* b = qobject_cast<QAbstractButton*>(w))
            add(out, b->text(), w);
        else if (auto* g = qobject_cast<QGroupBox*>(w))
            add(out, g->title(), w);
        else if (auto* d = qobject_cast<QDockWidget*>(w))
            add(out, d->windowTitle(), w);
        else if (auto* m = qobject_cast<QMenu*>(w))
            add(out, m->title(), w);
        else if (auto* e = qobject_cast<QLineEdit*>(w))
            add(out, e->placeholderText(), w);
        else if (auto* c = qobject_cast<QComboBox*>(w)) {
            for (int i = 0; i < c->count(); ++i) {
                add(out, c->itemText(i), w);
                add(out, c->itemData(i, Qt::ToolTipRole).toString(), w);
            }
        } else if (auto* t = qobject_cast<QTabBar*>(w)) {
            for (int i = 0; i < t->count(); ++i) {
                add(out, t->tabText(i), w);
                add(out, t->tabToolTip(i), w);
            }
        } else if (auto* h = qobject_cast<QHeaderView*>(w)) {
            if (h->model())
                for (int i = 0; i < h->count(); ++i)
                    add(out, h->model()->headerData(i, h->orientation()).toString(), w);
        } else if (auto* v = qobject_cast<QAbstractItemView*>(w)) {
            if (QAbstractItemModel* model = v->model())
                for (int r = 0; r < model->rowCount(); ++r)
                    for (int c = 0; c < model->columnCount(); ++c) {
                        add(out, model->index(r, c).data().toString(), w);
                        add(out, model->index(r, c).data(Qt::ToolTipRole).toString(), w);
                    }
        } else if (auto* b = qobject_cast<QTextEdit*>(w)) {
            if (b->isReadOnly())
                add(out, b->toPlainText(), w);
        } else if (auto* plot = qobject_cast<QCustomPlot*>(w)) {
            // a plot's axis titles, legend names and title texts
            for (QCPAxisRect* rect : plot->axisRects())
                for (QCPAxis* axis : rect->axes())
                    add(out, axis->label(), w);
            for (int i = 0; i < plot->plottableCount(); ++i)
                add(out, plot->plottable(i)->name(), w);
            for (int i = 0; i < plot->plotLayout()->elementCount(); ++i)
                if (auto* title = qobject_cast<QCPTextElement*>(plot->plotLayout()->elementAt(i)))
                    add(out, title->text(), w);
        }
    }
    return out;
}

// the CSV's column names (the Values dock lists them): the file's header, the same in every
// language
bool csvColumnName(const QString& text) {
    return csvColumnIndex(text.toStdString()).has_value();
}

// symbols, units, numbers, formulas and proper names read the same in both languages
bool languageFree(QString text) {
    static const QStringList names = {
        QStringLiteral("Chaplygin"), QStringLiteral("GSL"),       QStringLiteral("BDF"),
        QStringLiteral("Adams"),     QStringLiteral("Runge"),     QStringLiteral("Kutta"),
        QStringLiteral("Fehlberg"),  QStringLiteral("Cash"),      QStringLiteral("Karp"),
        QStringLiteral("Prince"),    QStringLiteral("Dormand"),   QStringLiteral("Gauss"),
        QStringLiteral("Newton"),    QStringLiteral("Pareto"),    QStringLiteral("atan2"),
        QStringLiteral("sqrt"),      QStringLiteral("sin"),       QStringLiteral("cos"),
        QStringLiteral("tan"),       QStringLiteral("exp"),       QStringLiteral("log"),
        QStringLiteral("cosh"),      QStringLiteral("sinh"),      QStringLiteral("tanh"),
        QStringLiteral("Ctrl"),      QStringLiteral("Shift"),     QStringLiteral("Alt"),
        QStringLiteral("PNG"),       QStringLiteral("SVG"),       QStringLiteral("PDF"),
        QStringLiteral("CSV"),       QStringLiteral("GIF"),       QStringLiteral("MP4"),
        QStringLiteral("JSON"),      QStringLiteral("rad"),       QStringLiteral("RK4"),
        QStringLiteral("English"),   QStringLiteral("Português"), QStringLiteral("Brasil"),
        QStringLiteral("max"),       QStringLiteral("min"),       QStringLiteral("Lab"),
        QStringLiteral("Hz"),        QStringLiteral("Home"),      QStringLiteral("End"),
        QStringLiteral("Backspace"), QStringLiteral("Page"),      QStringLiteral("Down"),
        QStringLiteral("Zoom"),      QStringLiteral("magenta"),   QStringLiteral("QAG"),
        QStringLiteral("RKF45"),     QStringLiteral("RK8PD")};
    if (text.startsWith(QLatin1String("chaplygin-lab "))) // a command line
        return true;
    text.remove(QRegularExpression(QStringLiteral("\\b[a-z0-9]+(_[a-z0-9]+)+\\b"))); // an id
    text.remove(QRegularExpression(QStringLiteral("\\S+\\.md\\b"))); // a file's name
    for (const QString& n : names)
        text.remove(QRegularExpression(QStringLiteral("\\b%1\\b").arg(n)));
    // no word of three letters or more is left
    return !text.contains(QRegularExpression(QStringLiteral("[A-Za-z]{3,}")));
}

QSet<QString> textSet(const QList<Shown>& shown) {
    QSet<QString> set;
    for (const Shown& s : shown)
        set.insert(s.text);
    return set;
}

// closes the modal dialog that `open` opens, after reading its texts
QList<Shown> modalTexts(const std::function<void()>& open) {
    QList<Shown> texts;
    QTimer::singleShot(0, qApp, [&texts] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal)
            return;
        texts = visibleTexts(modal);
        if (auto* d = qobject_cast<QDialog*>(modal))
            d->reject();
    });
    open();
    return texts;
}

// the labels and buttons whose text does not fit their width
QStringList clippedTexts(QWidget* window) {
    QStringList clipped;
    for (QWidget* w : window->findChildren<QWidget*>()) {
        if (!w->isVisible() || w->width() <= 0)
            continue;
        int needed = 0;
        QString text;
        if (auto* l = qobject_cast<QLabel*>(w); l && !l->wordWrap() && !l->text().isEmpty() &&
                                                l->pixmap().isNull() &&
                                                !w->inherits("chaplygin::ui::ElidedLabel")) {
            needed = l->minimumSizeHint().width();
            text = l->text();
        } else if (auto* b = qobject_cast<QAbstractButton*>(w);
                   b && !b->text().isEmpty() && !qobject_cast<QTabBar*>(w->parentWidget())) {
            needed = b->minimumSizeHint().width();
            text = b->text();
        } else
            continue;
        // narrower than its text, or cut by a parent (a scroll area without a horizontal bar):
        // a text scrolled out of sight vertically is not cut
        const QRect seen = w->visibleRegion().boundingRect();
        const int shown = seen.isEmpty() ? w->width() : std::min(w->width(), seen.width());
        if (shown < needed)
            clipped << QStringLiteral("%1 \"%2\": %3 px of %4")
                           .arg(describe(w), plain(text))
                           .arg(shown)
                           .arg(needed);
    }
    return clipped;
}

// the sinusoid with each system and in constant-speed mode, and the perturbed gallery scene: the
// parameters, the mode's line and the perturbation dock as each of them shows them
std::vector<Scene> variants() {
    std::vector<Scene> scenes;
    for (SystemKind kind : {SystemKind::Disk, SystemKind::Carriage}) {
        Scene s = presetScene("sinusoid");
        s.system.kind = kind;
        s.system.params = defaultSystemParams(kind);
        scenes.push_back(s);
    }
    Scene speed = presetScene("sinusoid");
    speed.mode = SpeedMode::Speed;
    speed.speed = 0.8;
    scenes.push_back(speed);
    scenes.push_back(galleryEntry("pushed-off-path").scene);
    return scenes;
}

// A known gap: the core's refusals (InputError) are English in both languages; the refused
// gallery entries show theirs, which are the only texts excused here
QSet<QString> coreRefusals() {
    QSet<QString> refusals;
    for (const GalleryEntry& e : galleryEntries()) {
        if (!e.rejected)
            continue;
        try {
            Solution::compute(e.scene);
        } catch (const InputError& error) {
            refusals.insert(QString::fromStdString(error.what()));
        }
    }
    return refusals;
}

void removeTranslators() {
    for (QTranslator* t : qApp->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
}

} // namespace

class TestPortugueseScreens : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void cleanup();
    void qtButtonsInPortuguese();
    void noEnglishLeftOnScreen();
    void helpGuideInPortuguese();
    void contextHelpFindsPortugueseSections();
    void nothingClipped_data();
    void nothingClipped();

  private:
    // every text of a window walked through its presets, gallery, docks, dialogs and help
    QList<Shown> tour();
};

void TestPortugueseScreens::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_portuguese_tests"));
}

void TestPortugueseScreens::cleanup() {
    removeTranslators();
}

QList<Shown> TestPortugueseScreens::tour() {
    QList<Shown> all;
    auto window = test::showTestWindow();
    if (!window)
        return all;
    window->resize(1600, 1000);
    all += visibleTexts(window.get());
    for (int i = 0; i < int(presetNames().size()); ++i) {
        window->choosePresetNumber(i);
        window->document()->flush();
        all += visibleTexts(window.get());
    }
    for (const GalleryEntry& e : galleryEntries()) {
        window->loadGalleryEntry(QString::fromStdString(e.name));
        window->document()->flush();
        all += visibleTexts(window.get());
    }
    for (const Scene& s : variants()) {
        window->loadScene(s);
        window->document()->flush();
        all += visibleTexts(window.get());
    }
    // the Methods dock with its diagram and table (the line is the quickest), then the Sweep dock
    window->choosePresetNumber(0);
    window->document()->flush();
    window->showMethodsDock();
    window->methodsPanel()->start();
    window->methodsPanel()->waitForFinished();
    QApplication::processEvents();
    all += visibleTexts(window.get());
    window->showSweepDock();
    QApplication::processEvents();
    all += visibleTexts(window.get());
    all += visibleTexts(window->showIntroduction());
    all += visibleTexts(window->showHelp());
    AnimationDialog animation(AnimationSettings{}, window.get());
    all += visibleTexts(&animation);
    // the About box and the question before discarding changes: Qt's message boxes
    for (QAction* a : window->findChildren<QAction*>())
        if (a->objectName() == QLatin1String("aboutAction") ||
            a->text().remove(u'&').startsWith(QLatin1String("About")) ||
            a->text().remove(u'&').startsWith(QLatin1String("Sobre")))
            all += modalTexts([a] { a->trigger(); });
    return all;
}

void TestPortugueseScreens::qtButtonsInPortuguese() {
    // the dialogs' standard buttons come from Qt's own catalogue (qt6-translations-l10n)
    QVERIFY(!app::installTranslations(*qApp, QLocale(QStringLiteral("pt_BR"))).isEmpty());
    QDialogButtonBox box(QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::Close |
                         QDialogButtonBox::Save | QDialogButtonBox::Discard |
                         QDialogButtonBox::Yes | QDialogButtonBox::No);
    QCOMPARE(plain(box.button(QDialogButtonBox::Cancel)->text()), QStringLiteral("Cancelar"));
    QCOMPARE(plain(box.button(QDialogButtonBox::Close)->text()), QStringLiteral("Fechar"));
    QCOMPARE(plain(box.button(QDialogButtonBox::Save)->text()), QStringLiteral("Salvar"));
    QCOMPARE(plain(box.button(QDialogButtonBox::Yes)->text()), QStringLiteral("Sim"));
    QCOMPARE(plain(box.button(QDialogButtonBox::No)->text()), QStringLiteral("Não"));
}

void TestPortugueseScreens::noEnglishLeftOnScreen() {
    const QList<Shown> english = tour();
    QVERIFY(english.size() > 500);
    const QSet<QString> englishTexts = textSet(english);
    // the walk reaches what the issue found untranslated
    for (const char* seen : {"A cusp: the sleigh backs up", "Close", "Compute work-precision"})
        QVERIFY2(std::any_of(
                     english.begin(), english.end(),
                     [seen](const Shown& s) { return s.text.contains(QString::fromUtf8(seen)); }),
                 seen);

    QVERIFY(!app::installTranslations(*qApp, QLocale(QStringLiteral("pt_BR"))).isEmpty());
    const QList<Shown> portuguese = tour();
    QVERIFY(portuguese.size() > 500);
    QStringList untranslated;
    QSet<QString> reported = coreRefusals();
    QVERIFY(!reported.isEmpty()); // the corner in constant-speed mode is refused
    for (const Shown& s : portuguese)
        if (englishTexts.contains(s.text) && !languageFree(s.text) && !reported.contains(s.text) &&
            !csvColumnName(s.text)) {
            reported.insert(s.text);
            untranslated << s.where + QStringLiteral(": ") + s.text;
        }
    for (const QString& u : untranslated) // QtTest cuts a long message: one line each
        qWarning().noquote() << "in English:" << u;
    QVERIFY2(untranslated.isEmpty(),
             qPrintable(QStringLiteral("%1 texts in English").arg(untranslated.size())));
}

void TestPortugueseScreens::helpGuideInPortuguese() {
    QVERIFY(!app::installTranslations(*qApp, QLocale(QStringLiteral("pt_BR"))).isEmpty());
    auto window = test::showTestWindow();
    QVERIFY(window);
    HelpWindow* help = window->showHelp(QStringLiteral("user-guide.md"));
    const QString text = help->browser()->toPlainText();
    QVERIFY2(text.startsWith(QStringLiteral("Chaplygin Lab — guia do usuário")),
             qPrintable(text.left(80)));
    // it starts with using the program: no build command near its start
    for (const char* build : {"cmake", "scripts/", "build/"})
        QVERIFY2(!text.left(1500).contains(QLatin1String(build)), build);
    // the document list still marks the guide as current
    QCOMPARE(help->findChild<QListWidget*>()->currentRow(), 0);
    // English again: the English guide
    removeTranslators();
    window.reset();
    window = test::showTestWindow();
    help = window->showHelp(QStringLiteral("user-guide.md"));
    QVERIFY2(
        help->browser()->toPlainText().startsWith(QStringLiteral("Chaplygin Lab — user guide")),
        qPrintable(help->browser()->toPlainText().left(80)));
}

void TestPortugueseScreens::contextHelpFindsPortugueseSections() {
    // F1 in a dock opens the Portuguese guide at that dock's section
    QVERIFY(!app::installTranslations(*qApp, QLocale(QStringLiteral("pt_BR"))).isEmpty());
    auto window = test::showTestWindow();
    QVERIFY(window);
    window->activateWindow();
    window->canvas()->setFocus();
    window->showContextHelp();
    HelpWindow* help = window->findChild<HelpWindow*>();
    QVERIFY(help);
    QTextBlock block = help->browser()->textCursor().block();
    QVERIFY(block.blockFormat().headingLevel() > 0);
    QCOMPARE(block.text(), QStringLiteral("Animação"));
    // every section F1 names has its heading in the Portuguese guide
    for (const char* section : {"The system and its parameters", "Choosing a path",
                                "Methods and accuracy", "Plots", "Animation"}) {
        const QString name = QCoreApplication::translate("chaplygin::ui::MainWindow", section);
        QVERIFY2(name != QLatin1String(section), section);
        QVERIFY2(help->showTopic(QStringLiteral("user-guide.md"), name), qPrintable(name));
        QCOMPARE(help->browser()->textCursor().block().text(), name);
    }
}

void TestPortugueseScreens::nothingClipped_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("size");
    for (const char* language : {"en", "pt_BR"})
        for (QSize size : {QSize(1024, 768), QSize(1920, 1080)})
            QTest::addRow("%s %dx%d", language, size.width(), size.height())
                << QString::fromLatin1(language) << size;
}

void TestPortugueseScreens::nothingClipped() {
    QFETCH(QString, language);
    QFETCH(QSize, size);
    if (language != QLatin1String("en"))
        QVERIFY(!app::installTranslations(*qApp, QLocale(language)).isEmpty());
    auto window = test::showTestWindow();
    QVERIFY(window);
    window->resize(size);
    QApplication::processEvents();
    QStringList clipped;
    // the docks as a first start lays them out, then each of the right and bottom tabs in front
    auto check = [&] {
        QApplication::processEvents();
        for (const QString& c : clippedTexts(window.get()))
            if (!clipped.contains(c))
                clipped << c;
    };
    check();
    window->showParametersDock();
    check();
    window->showMethodsDock();
    check();
    window->showSweepDock();
    check();
    for (QDockWidget* d : window->findChildren<QDockWidget*>()) {
        d->show();
        d->raise();
        check();
    }
    // the other systems, the speed mode and a perturbation, with their docks in front
    for (const Scene& s : variants()) {
        window->loadScene(s);
        window->document()->flush();
        for (const char* name : {"parametersDock", "perturbationDock", "accuracyDock"})
            if (auto* d = window->findChild<QDockWidget*>(QString::fromLatin1(name))) {
                d->raise();
                check();
            }
    }
    // the windows and the dialog the menus open, at their own sizes
    for (QWidget* w :
         std::initializer_list<QWidget*>{window->showIntroduction(), window->showHelp()}) {
        QApplication::processEvents();
        clipped += clippedTexts(w);
    }
    AnimationDialog animation(AnimationSettings{}, window.get());
    animation.show();
    QApplication::processEvents();
    clipped += clippedTexts(&animation);
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join(u'\n')));
}

QTEST_MAIN(TestPortugueseScreens)
#include "test_portuguese_screens.moc"
