#pragma once
#include <QLocale>
#include <QMenu>
#include <QString>

namespace chaplygin::ui {

/// The language the user chose under View > Language, kept in QSettings under "language": empty
/// for the system's locale, "en" or "pt_BR".
QString savedLanguage();
void saveLanguage(const QString& code);

/// The locale whose catalogue the program loads at start: the code if it names one ("en",
/// "pt_BR"), the system's locale if it is empty.
QLocale languageLocale(const QString& code);

/// View > Language: System, English, Português (Brasil), one checkable action each (the
/// language's own name). The choice is saved and takes effect at the next start; the strings are
/// set once when the window is built, so there is no live retranslation.
class LanguageMenu : public QMenu {
    Q_OBJECT
  public:
    explicit LanguageMenu(QWidget* parent = nullptr);
};

} // namespace chaplygin::ui
