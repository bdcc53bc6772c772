#include "shell/animation_dialog.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/file_dialogs.h"
#include "widgets/number_field.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>

#include <exception>

namespace chaplygin::ui {

namespace {
// what the exporter takes
constexpr int kMinFps = 1, kMaxFps = 120;
constexpr int kMinSide = 64, kMaxWidth = 7680, kMaxHeight = 4320;
const QString kFpsKey = QStringLiteral("animation/fps");
const QString kSizeKey = QStringLiteral("animation/size");
const QString kPlotsKey = QStringLiteral("animation/withPlots");
} // namespace

AnimationSettings AnimationDialog::remembered(AnimationSettings defaults) {
    QSettings settings;
    const int fps = settings.value(kFpsKey).toInt();
    if (fps >= kMinFps && fps <= kMaxFps)
        defaults.fps = fps;
    const QSize size = settings.value(kSizeKey).toSize();
    if (size.width() >= kMinSide && size.width() <= kMaxWidth && size.height() >= kMinSide &&
        size.height() <= kMaxHeight)
        defaults.size = size;
    if (settings.contains(kPlotsKey))
        defaults.withPlots = settings.value(kPlotsKey).toBool();
    return defaults;
}

void AnimationDialog::remember(const AnimationSettings& chosen) {
    QSettings settings;
    settings.setValue(kFpsKey, chosen.fps);
    settings.setValue(kSizeKey, chosen.size);
    settings.setValue(kPlotsKey, chosen.withPlots);
}

AnimationDialog::AnimationDialog(const AnimationSettings& initial, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Export animation"));
    m_file = new QLineEdit(initial.file);
    m_file->setPlaceholderText(tr("clip.gif, clip.mp4, or frames/ for PNG frames"));
    auto* browse = new QPushButton(tr("Browse\u2026"));
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    // whole numbers within what the exporter takes, each refused with its bound
    auto wholeNumber = [](const QString& name, int lo, int hi, int value) {
        auto* field = new NumberField(name);
        field->setIntegers(true);
        field->setMinimum(lo);
        field->setMaximum(hi);
        field->setZeroStep(1);
        field->setValue(value);
        return field;
    };
    m_fps = wholeNumber(tr("Frame rate"), kMinFps, kMaxFps, initial.fps);
    m_fps->setUnit(tr("fps"));
    m_width = wholeNumber(tr("width"), kMinSide, kMaxWidth, initial.size.width());
    m_height = wholeNumber(tr("height"), kMinSide, kMaxHeight, initial.size.height());
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("\u00d7")));
    sizeRow->addWidget(m_height);
    sizeRow->addWidget(new QLabel(tr("px")));
    sizeRow->addStretch();
    m_speed = new NumberField(tr("Speed"));
    m_speed->setMinimum(0.05);
    m_speed->setMaximum(100);
    m_speed->setValue(initial.speedFactor);
    m_speed->setUnit(tr("\u00d7 real time"));
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("animationError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_error->hide();
    for (NumberField* field : {m_fps, m_width, m_height, m_speed})
        connect(field, &NumberField::messageChanged, this, [this](const QString& message) {
            m_error->setText(message);
            m_error->setVisible(!message.isEmpty());
            adjustSize(); // the message's line, not a clipped note under it
        });
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
    form->addRow(m_error);
    form->addRow(note);
    form->addRow(buttons);
    connect(browse, &QPushButton::clicked, this, &AnimationDialog::browse);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (errorText().isEmpty()) // a refused value is not exported with the one before it
            accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

AnimationSettings AnimationDialog::settings() const {
    AnimationSettings s;
    s.file = m_file->text().trimmed();
    s.fps = int(m_fps->value());
    s.size = QSize(int(m_width->value()), int(m_height->value()));
    s.speedFactor = m_speed->value();
    s.withPlots = m_plots->isChecked();
    return s;
}

QString AnimationDialog::errorText() const {
    return m_error->isHidden() ? QString() : m_error->text();
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
