#pragma once
#include <QLocale>
#include <QMenu>
#include <QString>
#include <QStringList>

namespace chaplygin::ui {

/// The language the user chose under View > Language, kept in QSettings under "language": empty
/// for the system's locale, "en" or "pt_BR".
QString savedLanguage();
void saveLanguage(const QString& code);

/// The locale whose catalogue the program loads at start: the code if it names one ("en",
/// "pt_BR"), the system's locale if it is empty.
QLocale languageLocale(const QString& code);

/// Where Chaplygin Lab's catalogues are looked for, in order: share/chaplygin-lab/translations of
/// the program's installation prefix (installed beside bin/, so a distribution can update it
/// without a rebuild), then the catalogue compiled in under :/i18n (resources/translations/), which
/// serves a program run from its build tree.
QStringList catalogueDirectories();

/// Whether one of `directories` holds the catalogue of the language `code` ("pt_BR"); English,
/// the language of the sources, needs none.
bool catalogueAvailable(const QString& code,
                        const QStringList& directories = catalogueDirectories());

/// View > Language: System, English, Português (Brasil), one checkable action each (the
/// language's own name). The choice is saved and takes effect at the next start; the strings are
/// set once when the window is built, so there is no live retranslation. A language whose
/// catalogue is in none of `directories` is shown disabled, saying so.
class LanguageMenu : public QMenu {
    Q_OBJECT
  public:
    explicit LanguageMenu(QWidget* parent = nullptr,
                          const QStringList& directories = catalogueDirectories());
};

} // namespace chaplygin::ui
