// Long work of the studio (exports, level changes, the labelled scan) run on
// a worker thread while the window goes on: a progress dialog says what
// runs, Cancel stops it where the work checks for it, and the result comes
// back on the interface thread.
#pragma once

#include <QObject> // for QObject
#include <QString> // for QString

#include <atomic>     // for std::atomic
#include <functional> // for std::function

class QProgressDialog;
template <typename T>
class QFutureWatcher;

namespace meshpaint::studio {

class BackgroundTask : public QObject
{
public:
  //! `work` runs on a worker thread; it returns a line for the status bar
  //! and passes `cancelled` on to the engine (a CancelFlag), which looks at
  //! it between steps and leaves by throwing Cancelled: only then is the
  //! work cancelled (work that finished before it looked has finished). Any
  //! other exception out of it is the error. `done(ok, line)` runs on the
  //! interface thread when the work ends, before the task deletes itself.
  //! With `cancellable`, the dialog has a Cancel button.
  using Work = std::function<QString(const std::atomic<bool>& cancelled)>;
  using Done = std::function<void(bool ok, const QString& line)>;
  BackgroundTask(QWidget* parent, const QString& what, Work work, Done done, bool cancellable);
  ~BackgroundTask() override;

  //! Starts the work (returns at once).
  void start();
  //! Asks the work to stop at its next check.
  void cancel() { cancelled_ = true; }
  //! Whether the work stopped on cancel() (once it has ended).
  bool stopped() const { return stopped_; }
  bool running() const;
  QProgressDialog* dialog() { return dialog_; }

private:
  Work work_;
  Done done_;
  std::atomic<bool> cancelled_{false};
  bool stopped_ = false; //!< the work left by Cancelled
  QProgressDialog* dialog_;
  QFutureWatcher<QString>* watcher_;
  QString error_;
};

} // namespace meshpaint::studio
