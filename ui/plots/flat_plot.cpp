#include "plots/flat_plot.h"

#include "canvas/layer_blit.h"

#include <QPaintEvent>

namespace chaplygin::ui {

FlatPlot::FlatPlot(QWidget* parent) : QCustomPlot(parent) {
    // before the buffers are drawn: an immediate replot repaints before afterReplot
    connect(this, &QCustomPlot::beforeReplot, this, [this] { m_stale = true; });
}

void FlatPlot::paintEvent(QPaintEvent* event) {
    const bool opaque = mBackgroundBrush.style() == Qt::SolidPattern &&
                        mBackgroundBrush.color().alpha() == 255 && mBackgroundPixmap.isNull();
    if (!opaque || !m_flattened) {
        QCustomPlot::paintEvent(event);
        return;
    }
    const qreal dpr = devicePixelRatioF();
    const QSize pixels = (QSizeF(size()) * dpr).toSize();
    if (m_stale || m_flat.size() != pixels || m_flat.devicePixelRatio() != dpr) {
        m_flat = QImage(pixels, QImage::Format_RGB32);
        m_flat.setDevicePixelRatio(dpr);
        m_flat.fill(mBackgroundBrush.color());
        // what QCustomPlot::paintEvent draws, onto the image
        QCPPainter painter(&m_flat);
        painter.fillRect(mViewport, mBackgroundBrush);
        drawBackground(&painter);
        for (const auto& buffer : mPaintBuffers)
            buffer->draw(&painter);
        m_stale = false;
    }
    QPainter painter(this);
    blitRegion(painter, event->region(), m_flat);
}

} // namespace chaplygin::ui
