#include "document/math_text.h"

#include <QRegularExpression>
#include <QTextCursor>
#include <QTextDocument>

namespace chaplygin::ui {

namespace {

const QStringList& families() {
    static const QStringList f = {QStringLiteral("DejaVu Serif"), QStringLiteral("serif")};
    return f;
}

// a letter and the combining marks after it, the first of them a dot above
const QRegularExpression& dotted() {
    static const QRegularExpression re(QStringLiteral("(\\p{L}\\x{0307}\\p{M}*)"));
    return re;
}

} // namespace

QFont dottedSymbolFont(const QFont& base) {
    QFont font = base;
    font.setFamilies(families());
    return font;
}

QString withDottedSymbolFont(const QString& html) {
    QString out = html;
    out.replace(dotted(), QStringLiteral("<span style=\"font-family: '%1', %2\">\\1</span>")
                              .arg(families().at(0), families().at(1)));
    return out;
}

void setDottedSymbolFont(QTextDocument& document) {
    QTextCharFormat format;
    format.setFontFamilies(families());
    QTextCursor cursor(&document);
    while (true) {
        cursor = document.find(dotted(), cursor);
        if (cursor.isNull())
            break;
        cursor.mergeCharFormat(format);
    }
}

} // namespace chaplygin::ui
