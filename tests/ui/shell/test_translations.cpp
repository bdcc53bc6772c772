// Translations: the pt_BR catalogue (resources/translations/), installed or compiled in under
// :/i18n, the View > Language choice saved in the settings, and the screenshot mode's --language.
#include "desktop_entry.h"
#include "gui_test_support.h"
#include "shell/language_menu.h"
#include "shell/main_window.h"
#include "translations.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

void removeTranslators() {
    for (QTranslator* t : qApp->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
}

QStringList menuTitles(MainWindow& window) {
    QStringList titles;
    for (QAction* a : window.menuBar()->actions())
        titles << a->text();
    return titles;
}

// the titles of the docks, by object name
QMap<QString, QString> dockTitles(MainWindow& window) {
    QMap<QString, QString> titles;
    for (QDockWidget* d : window.findChildren<QDockWidget*>())
        titles[d->objectName()] = d->windowTitle();
    return titles;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void cleanup();
    void portugueseMenusAndDocks();
    void englishNeedsNoCatalogue();
    void installedCatalogueComesFirst();
    void languageChoiceSavedInSettings();
    void screenshotRefusesUnknownLanguage();
    void languageWithoutCatalogueNotOffered();
};

void TestTranslations::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_translation_tests"));
}

void TestTranslations::cleanup() {
    removeTranslators();
}

void TestTranslations::portugueseMenusAndDocks() {
    auto english = std::make_unique<MainWindow>(false);
    const QStringList englishMenus = menuTitles(*english);
    const QMap<QString, QString> englishDocks = dockTitles(*english);
    english.reset();
    QVERIFY(englishMenus.contains(QStringLiteral("&File")));

    QVERIFY(!app::installTranslations(*qApp, QLocale(QStringLiteral("pt_BR"))).isEmpty());
    MainWindow window(false);
    const QStringList menus = menuTitles(window);
    QVERIFY2(menus.contains(QStringLiteral("&Arquivo")), qPrintable(menus.join(u' ')));
    QVERIFY2(menus.contains(QStringLiteral("E&xibir")), qPrintable(menus.join(u' ')));
    QVERIFY2(menus.contains(QStringLiteral("A&juda")), qPrintable(menus.join(u' ')));
    // every menu of the bar and every dock has its own Portuguese title
    QCOMPARE(menus.size(), englishMenus.size());
    for (int i = 0; i < menus.size(); ++i)
        QVERIFY2(menus[i] != englishMenus[i], qPrintable(menus[i]));
    const QMap<QString, QString> docks = dockTitles(window);
    QCOMPARE(docks.keys(), englishDocks.keys());
    for (const QString& name : docks.keys())
        QVERIFY2(docks[name] != englishDocks[name], qPrintable(name + ": " + docks[name]));
    QCOMPARE(docks.value(QStringLiteral("pathDock")), QStringLiteral("Caminho"));
    QCOMPARE(docks.value(QStringLiteral("parametersDock")), QStringLiteral("Sistema e parâmetros"));
    // the View menu's Language submenu itself
    auto* language = window.findChild<QMenu*>(QStringLiteral("languageMenu"));
    QVERIFY(language);
    QCOMPARE(language->title(), QStringLiteral("&Idioma"));
}

void TestTranslations::englishNeedsNoCatalogue() {
    QVERIFY(app::installTranslations(*qApp, QLocale(QStringLiteral("en"))).isEmpty());
    MainWindow window(false);
    QVERIFY(menuTitles(window).contains(QStringLiteral("&File")));
    QCOMPARE(dockTitles(window).value(QStringLiteral("pathDock")), QStringLiteral("Path"));
}

void TestTranslations::installedCatalogueComesFirst() {
    // the installed share/chaplygin-lab/translations wins over the compiled-in copy; without it
    // the compiled-in one serves
    QTemporaryDir installed;
    QVERIFY(installed.isValid());
    const QString file = installed.filePath(QStringLiteral("chaplygin-lab_pt_BR.qm"));
    QVERIFY(QFile::copy(QStringLiteral(":/i18n/chaplygin-lab_pt_BR.qm"), file));
    const QLocale pt(QStringLiteral("pt_BR"));
    QCOMPARE(app::installTranslations(*qApp, pt, {installed.path(), QStringLiteral(":/i18n")}),
             file);
    MainWindow window(false);
    QVERIFY2(menuTitles(window).contains(QStringLiteral("&Arquivo")),
             qPrintable(menuTitles(window).join(u' ')));
    removeTranslators();
    QCOMPARE(
        app::installTranslations(
            *qApp, pt, {installed.filePath(QStringLiteral("absent")), QStringLiteral(":/i18n")}),
        QStringLiteral(":/i18n/chaplygin-lab_pt_BR.qm"));
    removeTranslators();
    // the program looks beside its own prefix first
    const QStringList dirs = catalogueDirectories();
    QCOMPARE(dirs.size(), 2);
    QVERIFY2(dirs[0].endsWith(QLatin1String("/share/chaplygin-lab/translations")),
             qPrintable(dirs[0]));
    QCOMPARE(dirs[1], QStringLiteral(":/i18n"));
}

void TestTranslations::languageChoiceSavedInSettings() {
    saveLanguage({});
    LanguageMenu menu;
    QStringList codes;
    QAction* portuguese = nullptr;
    for (QAction* a : menu.actions()) {
        if (!a->isCheckable())
            continue;
        codes << a->data().toString();
        if (a->data().toString() == QLatin1String("pt_BR"))
            portuguese = a;
        QCOMPARE(a->isChecked(), a->data().toString().isEmpty()); // "System" until one is chosen
    }
    QCOMPARE(codes, (QStringList{QString(), QStringLiteral("en"), QStringLiteral("pt_BR")}));
    QVERIFY(portuguese);
    portuguese->trigger();
    QCOMPARE(savedLanguage(), QStringLiteral("pt_BR"));
    QCOMPARE(languageLocale(savedLanguage()).name(), QStringLiteral("pt_BR"));
    QCOMPARE(languageLocale(QString()), QLocale::system());
    LanguageMenu again; // a new session shows the saved choice
    for (QAction* a : again.actions())
        if (a->isCheckable())
            QCOMPARE(a->isChecked(), a->data().toString() == QLatin1String("pt_BR"));
    saveLanguage({});
}

void TestTranslations::screenshotRefusesUnknownLanguage() {
    QByteArray file = QDir::temp().filePath(QStringLiteral("chaplygin-xx.png")).toUtf8();
    char a0[] = "chaplygin-lab", a1[] = "--screenshot", a3[] = "--language", a4[] = "xx";
    char* argv[] = {a0, a1, file.data(), a3, a4, nullptr};
    QCOMPARE(runScreenshot(5, argv), 2);
    QVERIFY(!QFileInfo::exists(QString::fromUtf8(file)));
}

void TestTranslations::languageWithoutCatalogueNotOffered() {
    QTemporaryDir empty;
    QVERIFY(!catalogueAvailable(QStringLiteral("pt_BR"), {empty.path()}));
    QVERIFY(catalogueAvailable(QStringLiteral("en"), {empty.path()})); // the sources' language
    QVERIFY(catalogueAvailable(QStringLiteral("pt_BR")));              // compiled in under :/i18n
    auto portugueseIn = [](const LanguageMenu& menu) -> QAction* {
        for (QAction* a : menu.actions())
            if (a->data().toString() == QLatin1String("pt_BR"))
                return a;
        return nullptr;
    };
    LanguageMenu without(nullptr, {empty.path()});
    QAction* missing = portugueseIn(without);
    QVERIFY(missing);
    QVERIFY(!missing->isEnabled());
    QVERIFY2(missing->text().contains(QLatin1String("not installed")), qPrintable(missing->text()));
    LanguageMenu with;
    QAction* offered = portugueseIn(with);
    QVERIFY(offered && offered->isEnabled());
    QCOMPARE(offered->text(), QStringLiteral("Portugu\u00eas (Brasil)"));
}

QTEST_MAIN(TestTranslations)
#include "test_translations.moc"
