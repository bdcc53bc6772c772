#pragma once
// Symbols with a combining dot above (φ̇, χ̇, Ψ̇: U+0307 after a letter) set in a font that
// places the dot. DejaVu Sans, the usual sans-serif face on Linux, has no anchor for the dot on
// Greek letters, and Qt then draws it away from its letter, even a line higher.
#include <QFont>
#include <QString>

class QTextDocument;

namespace chaplygin::ui {

/// A serif face whose marks sit on Greek letters (DejaVu Serif, else the system's serif).
QFont dottedSymbolFont(const QFont& base);
/// Rich text: every letter with a combining dot wrapped in a span of dottedSymbolFont's family.
/// The text must already be HTML (escaped where it was plain).
QString withDottedSymbolFont(const QString& html);
/// The same on a laid-out document (Markdown notes).
void setDottedSymbolFont(QTextDocument& document);

} // namespace chaplygin::ui
