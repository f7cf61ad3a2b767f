#include "BackgroundTask.h"

#include <QFutureWatcher>     // for QFutureWatcher
#include <QProgressDialog>    // for QProgressDialog
#include <QtConcurrent>       // for QtConcurrent::run

#include "core/cancellation.h" // for meshpaint::Cancelled

#include <exception> // for std::exception

namespace meshpaint::studio {

BackgroundTask::BackgroundTask(QWidget* parent, const QString& what, Work work, Done done, bool cancellable)
  : QObject(parent), work_(std::move(work)), done_(std::move(done)), watcher_(new QFutureWatcher<QString>(this))
{
  dialog_ = new QProgressDialog(what, cancellable ? "Cancel" : QString(), 0, 0, parent);
  dialog_->setObjectName("progress");
  dialog_->setWindowTitle("meshpaint");
  dialog_->setWindowModality(Qt::NonModal); // the view stays usable: the camera turns meanwhile
  dialog_->setMinimumDuration(300);         // quick work shows no dialog
  dialog_->setAutoClose(false);
  dialog_->setAutoReset(false);
  connect(dialog_, &QProgressDialog::canceled, [this] {
    cancel();
    dialog_->setLabelText(dialog_->labelText() + " (cancelling)");
  });
  connect(watcher_, &QFutureWatcher<QString>::finished, [this] {
    const bool ok = error_.isEmpty() && !stopped_;
    const QString line = stopped_ ? "cancelled" : ok ? watcher_->result() : error_;
    dialog_->hide();
    if (done_)
      done_(ok, line);
    deleteLater();
  });
}

BackgroundTask::~BackgroundTask()
{
  cancelled_ = true;
  watcher_->waitForFinished(); // the work holds references into the window
  delete dialog_;
}

void BackgroundTask::start()
{
  dialog_->setValue(0); // starts the dialog's timer
  watcher_->setFuture(QtConcurrent::run([this]() -> QString {
    try {
      return work_(cancelled_);
    } catch (const Cancelled&) {
      stopped_ = true; // read after the future finished
    } catch (const std::exception& e) {
      error_ = QString::fromStdString(e.what());
    } catch (...) {
      error_ = "the work failed";
    }
    return QString();
  }));
}

bool BackgroundTask::running() const { return watcher_->isRunning(); }

} // namespace meshpaint::studio
