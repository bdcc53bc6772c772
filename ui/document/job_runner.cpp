#include "document/job_runner.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

namespace chaplygin::ui {

JobRunner::JobRunner(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &JobRunner::onFinished);
}

JobRunner::~JobRunner() {
    m_watcher.disconnect(this);
    cancel();
    m_watcher.waitForFinished();
}

bool JobRunner::start(Job job) {
    if (m_running)
        return false;
    m_running = true;
    quint64 run = ++m_runId;
    m_stop = std::make_shared<std::atomic<bool>>(false);
    QPointer<JobRunner> self(this);
    m_watcher.setFuture(QtConcurrent::run([this, self, run, stop = m_stop, job = std::move(job)] {
        Progress report = [this, self, run](int done, int total) {
            // queued to the UI thread; a later job's runner ignores an older job's progress
            QMetaObject::invokeMethod(
                this,
                [this, self, run, done, total] {
                    if (self && run == m_runId && m_running)
                        emit progress(done, total);
                },
                Qt::QueuedConnection);
        };
        job(*stop, report);
    }));
    return true;
}

void JobRunner::cancel() {
    if (m_stop)
        m_stop->store(true);
}

void JobRunner::waitForFinished() {
    if (!m_running)
        return;
    m_watcher.waitForFinished();
    QCoreApplication::sendPostedEvents(this); // the job's last progress reports
    onFinished();
}

void JobRunner::onFinished() {
    if (!m_running)
        return;
    m_running = false;
    emit finished();
}

} // namespace chaplygin::ui
