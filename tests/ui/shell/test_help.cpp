// Help: the About text, the Markdown documents rendered from the resources, F1 opening the
// section about the part of the window that has the focus. Offscreen, real widgets.
#include "canvas/scene_canvas.h"
#include "panels/parameters_panel.h"
#include "shell/help_window.h"
#include "shell/markdown_browser.h"
#include "version.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QFile>
#include <QImage>
#include <QPointer>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTextBlock>
#include <QTextBrowser>
#include <QtTest>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestHelp : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_help_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void aboutNamesVersionLicenceCreditsPaper();
    void helpRendersDocsFromResources();
    void documentsAreParsedApartAndReplaced();
    void f1OpensSectionOfFocus();
    void sectionHeadingAtTheTop();
    void picturesFitTheWidth();
    void everyPictureOfTheHelpLoads();
    void helpWindowFitsTheScreen();
    void userGuideStartsWithUsingTheProgram();
};

void TestHelp::aboutNamesVersionLicenceCreditsPaper() {
    const QString about = MainWindow::aboutText();
    QVERIFY(about.contains(QStringLiteral(CHAPLYGIN_LAB_VERSION)));
    QVERIFY(QStringLiteral(CHAPLYGIN_LAB_VERSION).contains(QLatin1Char('.')));
    QVERIFY(about.contains(QStringLiteral("Licence")));
    QVERIFY(about.contains(QStringLiteral("Credits")));
    QVERIFY(about.contains(QStringLiteral("Antunes")));
    QVERIFY(about.contains(QStringLiteral("Controlling nonholonomic Chaplygin systems")));
    QVERIFY(about.contains(QString::fromLatin1(qVersion())));
}

void TestHelp::helpRendersDocsFromResources() {
    HelpWindow* help = m_window->showHelp(QStringLiteral("physics.md"));
    QVERIFY(help->isVisible());
    // the compiled-in document is the repository's docs/physics.md, byte for byte
    QFile compiled(QStringLiteral(":/help/physics.md"));
    QFile source(QStringLiteral(CHAPLYGIN_SOURCE_DIR "/docs/physics.md"));
    QVERIFY(compiled.open(QIODevice::ReadOnly) && source.open(QIODevice::ReadOnly));
    QCOMPARE(compiled.readAll(), source.readAll());
    for (const QString& doc : HelpWindow::documents())
        QVERIFY2(QFile::exists(QStringLiteral(":/help/") + doc), qPrintable(doc));
    // rendered as Markdown: the first line is a level-1 heading without its '#'
    QTextBlock first = help->browser()->document()->begin();
    while (first.isValid() && first.text().isEmpty())
        first = first.next();
    QCOMPARE(first.blockFormat().headingLevel(), 1);
    QVERIFY(!first.text().startsWith(QLatin1Char('#')));
    QVERIFY(help->browser()->toPlainText().contains(QStringLiteral("Antunes")));
    // the pictures are there too: an image of the user guide loads from the resources
    QVERIFY(help->showTopic(QStringLiteral("user-guide.md")));
    QVERIFY(!QImage(QStringLiteral(":/help/images/main-window-sinusoid.png")).isNull());
    QVERIFY(!help->showTopic(QStringLiteral("no-such.md")));
}

void TestHelp::documentsAreParsedApartAndReplaced() {
    // each document is parsed into a document of its own before it is shown (QTextBrowser's own
    // loading laid out the shown document at every insertion); the one it replaces is deleted,
    // and a relative link ("physics.md", as a click on it gives) opens the document it names
    HelpWindow* help = m_window->showHelp(QStringLiteral("numerics.md"));
    auto* browser = qobject_cast<MarkdownBrowser*>(help->browser());
    QVERIFY(browser);
    QPointer<QTextDocument> numerics = browser->document();
    QCOMPARE(numerics->parent(), browser);
    QVERIFY(browser->toPlainText().contains(QStringLiteral("DOP853")));
    QSignalSpy changed(browser, &QTextBrowser::sourceChanged);
    browser->setSource(QUrl(QStringLiteral("physics.md")));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(help->currentDocument(), QStringLiteral("physics.md"));
    QVERIFY(numerics.isNull());
    QVERIFY(browser->toPlainText().contains(QStringLiteral("Antunes")));
    QTextBlock first = browser->document()->begin();
    while (first.isValid() && first.text().isEmpty())
        first = first.next();
    QCOMPARE(first.blockFormat().headingLevel(), 1);
    // the same document again is not parsed again
    QPointer<QTextDocument> physics = browser->document();
    QVERIFY(help->showTopic(QStringLiteral("physics.md"), QStringLiteral("control law")));
    QVERIFY(!physics.isNull());
    QCOMPARE(browser->document(), physics.data());
}

void TestHelp::f1OpensSectionOfFocus() {
    m_window->showParametersDock();
    NumberField* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setFocus();
    QApplication::processEvents();
    QTest::keyClick(m, Qt::Key_F1);
    HelpWindow* help = m_window->findChild<HelpWindow*>();
    QVERIFY(help && help->isVisible());
    QCOMPARE(help->currentDocument(), QStringLiteral("user-guide.md"));
    QTextBlock block = help->browser()->textCursor().block();
    QVERIFY(block.blockFormat().headingLevel() > 0);
    QVERIFY2(block.text().contains(QStringLiteral("parameters")), qPrintable(block.text()));
    // from the canvas: the animation section
    m_window->activateWindow();
    m_window->canvas()->setFocus();
    m_window->showContextHelp();
    QVERIFY(help->browser()->textCursor().block().text().contains(QStringLiteral("Animation")));
}

void TestHelp::sectionHeadingAtTheTop() {
    // F1 shows the section from its heading down, not the end of the section before it
    for (const char* section : {"Animation", "Plots", "Presentation mode"}) {
        HelpWindow* help =
            m_window->showHelp(QStringLiteral("user-guide.md"), QString::fromLatin1(section));
        QApplication::processEvents();
        QTextBlock heading = help->browser()->textCursor().block();
        QVERIFY2(heading.text().contains(QString::fromLatin1(section)), section);
        const int top = help->browser()->cursorRect().top();
        QVERIFY2(
            top >= 0 && top < 3 * help->browser()->fontMetrics().height(),
            qPrintable(QStringLiteral("%1 at %2 px").arg(QString::fromLatin1(section)).arg(top)));
    }
}

void TestHelp::picturesFitTheWidth() {
    // the user guide's screenshots (1280 px and wider) are shown scaled to the window, no
    // sideways scrolling; narrowed, the window scales them again
    HelpWindow* help = m_window->showHelp(QStringLiteral("user-guide.md"));
    for (QSize size : {QSize(900, 700), QSize(600, 500)}) {
        help->resize(size);
        QApplication::processEvents();
        QTRY_COMPARE(help->browser()->horizontalScrollBar()->maximum(), 0);
    }
    int pictures = 0;
    for (QTextBlock b = help->browser()->document()->begin(); b.isValid(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it)
            pictures += it.fragment().charFormat().isImageFormat() ? 1 : 0;
    QVERIFY(pictures >= 3);
}

void TestHelp::everyPictureOfTheHelpLoads() {
    // each picture a help document shows is compiled in (a missing one is drawn as a broken icon)
    HelpWindow* help = m_window->showHelp();
    int pictures = 0;
    for (const QString& doc : HelpWindow::documents()) {
        QVERIFY(help->showTopic(doc));
        QTextDocument* text = help->browser()->document();
        for (QTextBlock b = text->begin(); b.isValid(); b = b.next())
            for (auto it = b.begin(); !it.atEnd(); ++it) {
                const QTextCharFormat format = it.fragment().charFormat();
                if (!format.isImageFormat())
                    continue;
                const QString name = format.toImageFormat().name();
                ++pictures;
                QVERIFY2(!QImage(QStringLiteral(":/help/") + name).isNull(),
                         qPrintable(QStringLiteral("%1: %2").arg(doc, name)));
            }
    }
    QVERIFY(pictures >= 10);
}

// the help window opens inside the screen's free area, at most 900 x 700 and never taller or
// wider than the screen (a 900 x 700 window ran off the bottom of a 1080 screen placed below the
// main window's title)
void TestHelp::helpWindowFitsTheScreen() {
    m_window->move(0, 0);
    HelpWindow* help = m_window->showHelp(QStringLiteral("user-guide.md"));
    QApplication::processEvents();
    const QRect available = m_window->screen()->availableGeometry();
    QVERIFY2(available.width() < 900 || available.height() < 700,
             "the test needs a screen smaller than the help window's own size");
    QVERIFY2(available.contains(help->frameGeometry()),
             qPrintable(QStringLiteral("help %1,%2 %3x%4 on a screen of %5x%6")
                            .arg(help->frameGeometry().x())
                            .arg(help->frameGeometry().y())
                            .arg(help->frameGeometry().width())
                            .arg(help->frameGeometry().height())
                            .arg(available.width())
                            .arg(available.height())));
    QVERIFY(help->width() >= available.width() / 2);
    QVERIFY(help->height() >= available.height() / 2);
}

// Help > User guide opens on how to use the program: its first screen names Space, the presets'
// keys and What am I looking at?, and no build command or source folder (they come later)
void TestHelp::userGuideStartsWithUsingTheProgram() {
    HelpWindow* help = m_window->showHelp(QStringLiteral("user-guide.md"));
    const QString text = help->browser()->document()->toPlainText();
    const qsizetype window = text.indexOf(QStringLiteral("\nThe window\n"));
    QVERIFY(window > 0);
    const QString start = text.left(window);
    for (const QString& word : {QStringLiteral("Space"), QStringLiteral("1 to 4"),
                                QStringLiteral("What am I looking at?")})
        QVERIFY2(start.contains(word), qPrintable(word));
    for (const QString& word :
         {QStringLiteral("scripts/"), QStringLiteral("build/"), QStringLiteral("cmake")})
        QVERIFY2(!start.contains(word), qPrintable(word));
    QVERIFY(text.indexOf(QStringLiteral("scripts/run")) > window); // still in the guide
}

QTEST_MAIN(TestHelp)
#include "test_help.moc"
