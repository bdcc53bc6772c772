#pragma once
#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>

namespace chaplygin::ui {

/// Runs one long job at a time off the UI thread (a parameter sweep, a work-precision chart):
/// the job gets a stop flag to poll and a progress callback it may call from its thread; the
/// runner hands progress and the end to the UI thread as signals. Results travel in whatever
/// the job captured (e.g. a shared_ptr the owner reads on finished()).
class JobRunner : public QObject {
    Q_OBJECT
  public:
    using Progress = std::function<void(int done, int total)>;
    using Job = std::function<void(const std::atomic<bool>& stop, const Progress& progress)>;

    explicit JobRunner(QObject* parent = nullptr);
    /// Asks a running job to stop and waits for it.
    ~JobRunner() override;

    bool isRunning() const { return m_running; }
    /// Starts a job; returns false (and does nothing) while another one runs.
    bool start(Job job);
    /// Asks the running job to stop at its next poll; never blocks.
    void cancel();
    /// Whether the last job was asked to stop.
    bool cancelRequested() const { return m_stop && m_stop->load(); }
    /// Blocks until the running job has ended and finished() has been emitted.
    void waitForFinished();

  signals:
    /// From the UI thread, for the job under way only.
    void progress(int done, int total);
    /// The job has ended (completed, cancelled, or thrown: see the job's own result).
    void finished();

  private:
    void onFinished();

    quint64 m_runId = 0;
    bool m_running = false;
    std::shared_ptr<std::atomic<bool>> m_stop;
    QFutureWatcher<void> m_watcher;
};

} // namespace chaplygin::ui
