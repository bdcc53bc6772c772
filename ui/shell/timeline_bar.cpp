#include "shell/timeline_bar.h"

#include "shell/playback.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QEvent>
#include <QLabel>
#include <QMenu>
#include <QSlider>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {
constexpr int kSliderSteps = 2000;

// x1/16 ... x1/2 as fractions, x1 ... x64 as whole numbers
QString speedLabel(double factor) {
    return factor < 1 ? QStringLiteral("\u00d71/%1").arg(std::lround(1 / factor))
                      : QStringLiteral("\u00d7%1").arg(std::lround(factor));
}

int normalSpeedIndex() {
    return int(std::find(kPlaybackSpeeds.begin(), kPlaybackSpeeds.end(), 1.0) -
               kPlaybackSpeeds.begin());
}
} // namespace

TimelineBar::TimelineBar(Playback* playback, QWidget* parent)
    : QToolBar(tr("Timeline"), parent), m_playback(playback) {
    setObjectName(QStringLiteral("timeline"));
    m_stepBack = addAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Step &back"));
    m_stepBack->setShortcut(Qt::Key_Comma);
    m_stepBack->setToolTip(tr("One frame back at the current speed (,); Shift+, one second"));
    m_play = addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("&Play"));
    m_play->setShortcut(Qt::Key_Space);
    m_play->setToolTip(tr("Play or pause (Space)"));
    m_stepForward =
        addAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("Step &forward"));
    m_stepForward->setShortcut(Qt::Key_Period);
    m_stepForward->setToolTip(tr("One frame forward at the current speed (.); Shift+. one second"));
    m_loop = addAction(tr("Loop"));
    m_loop->setCheckable(true);
    m_loop->setToolTip(tr("Start again at the end"));
    m_speed = new QComboBox;
    for (double f : kPlaybackSpeeds)
        m_speed->addItem(speedLabel(f), f);
    m_speed->setCurrentIndex(normalSpeedIndex());
    m_speed->setMaxVisibleItems(int(kPlaybackSpeeds.size()));
    m_speed->setToolTip(
        tr("Playback speed: simulated seconds per real second ([ slower, ] faster)"));
    addWidget(m_speed);
    m_faster = new QAction(tr("&Faster"), this);
    m_faster->setShortcut(Qt::Key_BracketRight);
    m_slower = new QAction(tr("&Slower"), this);
    m_slower->setShortcut(Qt::Key_BracketLeft);
    m_normalSpeed = new QAction(tr("&Normal speed (\u00d7%1)").arg(1), this);
    m_normalSpeed->setShortcut(Qt::Key_Backspace);
    connect(m_faster, &QAction::triggered, this, [this] {
        m_speed->setCurrentIndex(std::min(m_speed->currentIndex() + 1, m_speed->count() - 1));
    });
    connect(m_slower, &QAction::triggered, this,
            [this] { m_speed->setCurrentIndex(std::max(m_speed->currentIndex() - 1, 0)); });
    connect(m_normalSpeed, &QAction::triggered, this,
            [this] { m_speed->setCurrentIndex(normalSpeedIndex()); });
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setRange(0, kSliderSteps);
    m_slider->setToolTip(tr("Scrub through time"));
    m_slider->setMinimumWidth(200);
    m_slider->setAccessibleName(tr("Time"));
    m_slider->setAccessibleDescription(tr("The animation time; arrows and Page Up/Down scrub"));
    addWidget(m_slider);
    m_timeLabel = new QLabel;
    m_timeLabel->setAccessibleName(tr("Time read-out"));
    addWidget(m_timeLabel);

    // Home/End and one-second steps: window shortcuts without buttons of their own
    m_start = new QAction(tr("Go to the &start"), this);
    m_start->setShortcut(Qt::Key_Home);
    m_end = new QAction(tr("Go to the &end"), this);
    m_end->setShortcut(Qt::Key_End);
    m_secondBack = new QAction(tr("One second back"), this);
    m_secondBack->setShortcuts(
        {QKeySequence(Qt::SHIFT | Qt::Key_Comma), QKeySequence(Qt::SHIFT | Qt::Key_Less)});
    m_secondForward = new QAction(tr("One second forward"), this);
    m_secondForward->setShortcuts(
        {QKeySequence(Qt::SHIFT | Qt::Key_Period), QKeySequence(Qt::SHIFT | Qt::Key_Greater)});
    // through m_playback: the clock shown can change (setPlayback)
    connect(m_start, &QAction::triggered, this, [this] { m_playback->goToStart(); });
    connect(m_end, &QAction::triggered, this, [this] { m_playback->goToEnd(); });
    connect(m_secondBack, &QAction::triggered, this,
            [this] { m_playback->stepBy(-Playback::kLargeStep); });
    connect(m_secondForward, &QAction::triggered, this,
            [this] { m_playback->stepBy(Playback::kLargeStep); });
    setAccessibleName(tr("Timeline"));
    m_play->setObjectName(QStringLiteral("playAction"));
    connect(m_play, &QAction::triggered, this, [this] { m_playback->togglePlay(); });
    connect(m_stepBack, &QAction::triggered, this, [this] { m_playback->stepBackward(); });
    connect(m_stepForward, &QAction::triggered, this, [this] { m_playback->stepForward(); });
    connect(m_loop, &QAction::toggled, this, [this](bool on) { m_playback->setLoop(on); });
    connect(m_speed, &QComboBox::currentIndexChanged, this, [this](int i) {
        m_playback->setSpeedFactor(m_speed->itemData(i).toDouble());
        m_faster->setEnabled(i + 1 < m_speed->count());
        m_slower->setEnabled(i > 0);
    });
    connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
        if (!m_syncing)
            m_playback->seek(m_playback->tEnd() * v / kSliderSteps);
    });
    connectClock();
    sync();
}

void TimelineBar::connectClock() {
    m_clockConnections = {
        connect(m_playback, &Playback::timeChanged, this, &TimelineBar::sync),
        connect(m_playback, &Playback::playingChanged, this, &TimelineBar::showPlaying)};
    showPlaying(m_playback->isPlaying());
}

void TimelineBar::showPlaying(bool playing) {
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("&Pause") : tr("&Play"));
}

void TimelineBar::setPlayback(Playback* playback) {
    if (playback == m_playback)
        return;
    for (const QMetaObject::Connection& c : m_clockConnections)
        disconnect(c);
    m_playback->pause(); // the clock no longer shown stands still
    m_playback = playback;
    // the speed and the loop chosen on the bar are the new clock's too
    m_playback->setSpeedFactor(m_speed->currentData().toDouble());
    m_playback->setLoop(m_loop->isChecked());
    connectClock();
    sync();
}

QMenu* TimelineBar::makeSpeedMenu(QWidget* parent) {
    auto* menu = new QMenu(tr("Spee&d"), parent);
    menu->setObjectName(QStringLiteral("speedMenu"));
    menu->addAction(m_faster);
    menu->addAction(m_slower);
    menu->addAction(m_normalSpeed);
    menu->addSeparator();
    auto* group = new QActionGroup(menu);
    for (int i = 0; i < m_speed->count(); ++i) {
        QAction* speed = menu->addAction(m_speed->itemText(i));
        speed->setCheckable(true);
        speed->setChecked(i == m_speed->currentIndex());
        group->addAction(speed);
        connect(speed, &QAction::triggered, this, [this, i] { m_speed->setCurrentIndex(i); });
    }
    connect(m_speed, &QComboBox::currentIndexChanged, menu,
            [group](int i) { group->actions().at(i)->setChecked(true); });
    return menu;
}

void TimelineBar::changeEvent(QEvent* event) {
    QToolBar::changeEvent(event);
    // after the children, the read-out among them, have the new font too
    if (event->type() == QEvent::FontChange)
        QMetaObject::invokeMethod(this, &TimelineBar::sync, Qt::QueuedConnection);
}

void TimelineBar::sync() {
    m_syncing = true;
    double end = m_playback->tEnd();
    m_slider->setValue(
        end > 0 ? static_cast<int>(std::lround(m_playback->time() / end * kSliderSteps)) : 0);
    auto text = [&](double t) {
        return tr(" t = %1 s / %2 s").arg(t, 0, 'f', 2).arg(end, 0, 'f', 2);
    };
    // a size that fits every time up to the end: a new text then lays out the label alone,
    // not the whole window
    if (end != m_labelEnd || m_timeLabel->font() != m_labelFont) {
        m_labelEnd = end;
        m_labelFont = m_timeLabel->font();
        m_timeLabel->setMinimumSize(0, 0);
        m_timeLabel->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
        m_timeLabel->setText(text(std::max(end, 0.0)));
        QSize widest = m_timeLabel->sizeHint();
        m_timeLabel->setFixedSize(
            std::max(widest.width() + m_timeLabel->fontMetrics().averageCharWidth(), 150),
            widest.height());
    }
    m_timeLabel->setText(text(m_playback->time()));
    m_syncing = false;
}

} // namespace chaplygin::ui
