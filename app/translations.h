#pragma once

class QCoreApplication;
class QLocale;

namespace chaplygin::app {

/// Installs Qt's own translation and Chaplygin Lab's catalogue (resources/translations/, compiled
/// in under
/// :/i18n) for the locale's UI languages, e.g. pt_BR. Returns whether a catalogue of Chaplygin Lab
/// was found; English needs none.
bool installTranslations(QCoreApplication& app, const QLocale& locale);

} // namespace chaplygin::app
