#include "shell/animation_dialog.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/file_dialogs.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>

#include <exception>

namespace chaplygin::ui {

AnimationDialog::AnimationDialog(const AnimationSettings& initial, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Export animation"));
    m_file = new QLineEdit(initial.file);
    m_file->setPlaceholderText(tr("clip.gif, clip.mp4, or frames/ for PNG frames"));
    auto* browse = new QPushButton(tr("Browse\u2026"));
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    m_fps = new QSpinBox;
    m_fps->setRange(1, 120);
    m_fps->setValue(initial.fps);
    m_fps->setSuffix(tr(" fps"));
    m_width = new QSpinBox;
    m_width->setRange(64, 7680);
    m_width->setValue(initial.size.width());
    m_height = new QSpinBox;
    m_height->setRange(64, 4320);
    m_height->setValue(initial.size.height());
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("\u00d7")));
    sizeRow->addWidget(m_height);
    sizeRow->addWidget(new QLabel(tr("px")));
    sizeRow->addStretch();
    m_speed = new QDoubleSpinBox;
    m_speed->setRange(0.05, 100);
    m_speed->setDecimals(2);
    m_speed->setValue(initial.speedFactor);
    m_speed->setSuffix(tr(" \u00d7 real time"));
    m_plots = new QCheckBox(tr("Plots beside the canvas"));
    m_plots->setChecked(initial.withPlots);
    auto* note = new QLabel(tr("GIF and MP4 need the ffmpeg program; a folder gets PNG frames."));
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("File"), fileRow);
    form->addRow(tr("Frame rate"), m_fps);
    form->addRow(tr("Size"), sizeRow);
    form->addRow(tr("Speed"), m_speed);
    form->addRow(QString(), m_plots);
    form->addRow(note);
    form->addRow(buttons);
    connect(browse, &QPushButton::clicked, this, &AnimationDialog::browse);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

AnimationSettings AnimationDialog::settings() const {
    AnimationSettings s;
    s.file = m_file->text().trimmed();
    s.fps = m_fps->value();
    s.size = QSize(m_width->value(), m_height->value());
    s.speedFactor = m_speed->value();
    s.withPlots = m_plots->isChecked();
    return s;
}

void AnimationDialog::browse() {
    const QFileInfo current(m_file->text().trimmed());
    QString path = chooseSaveFile(
        this, tr("Export animation"), QStringLiteral("animation"),
        current.completeBaseName().isEmpty() ? QStringLiteral("clip") : current.completeBaseName(),
        tr("MP4 video (*.mp4);;GIF (*.gif);;PNG frames into a folder (*)"));
    if (!path.isEmpty())
        m_file->setText(path);
}

bool exportAnimationWithProgress(QWidget* parent, SceneDocument* document,
                                 const AnimationSettings& settings, QString* error) {
    error->clear();
    try {
        AnimationExporter exporter(document, settings);
        QProgressDialog progress(
            QCoreApplication::translate("AnimationDialog", "Rendering %1 frames\u2026")
                .arg(exporter.frameCount()),
            QCoreApplication::translate("AnimationDialog", "Cancel"), 0, exporter.frameCount(),
            parent);
        progress.setObjectName(QStringLiteral("animationProgress"));
        progress.setWindowModality(Qt::WindowModal);
        progress.setMinimumDuration(0);
        progress.setValue(0);
        return exporter.run([&](int done, int) {
            progress.setValue(done);
            QCoreApplication::processEvents();
            return !progress.wasCanceled();
        });
    } catch (const InputError& e) {
        *error = QString::fromStdString(e.what());
    } catch (const IoError& e) {
        *error = QString::fromStdString(e.what());
    } catch (const std::exception& e) {
        *error = QString::fromStdString(e.what());
    }
    return false;
}

} // namespace chaplygin::ui
