#include "FitDialog.h"

#include <QLabel>         // for QLabel
#include <QPlainTextEdit> // for QPlainTextEdit
#include <QProcess>       // for QProcess
#include <QProgressBar>   // for QProgressBar
#include <QPushButton>    // for QPushButton
#include <QVBoxLayout>    // for QVBoxLayout

namespace meshpaint::studio {

FitDialog::FitDialog(const QString& program, const QString& scan, const QString& out,
                     std::function<void(bool)> done, QWidget* parent)
  : QDialog(parent), program_(program), scan_(scan), out_(out), done_(std::move(done)), process_(new QProcess(this))
{
  setWindowTitle("Fit a scan");
  auto* layout = new QVBoxLayout(this);
  status_ = new QLabel("fitting " + scan + " into " + out);
  busy_ = new QProgressBar;
  busy_->setRange(0, 0); // the steps of a fit have no known count: busy
  log_ = new QPlainTextEdit;
  log_->setReadOnly(true);
  cancel_ = new QPushButton("Cancel");
  cancel_->setObjectName("cancel");
  for (QWidget* w : std::initializer_list<QWidget*>{status_, busy_, log_, cancel_})
    layout->addWidget(w);
  resize(640, 320);
  connect(cancel_, &QPushButton::clicked, [this] { running() ? cancel() : accept(); });
  // Progress comes on stderr, one line per step; the report on stdout.
  connect(process_, &QProcess::readyReadStandardError,
          [this] { log_->appendPlainText(QString::fromLocal8Bit(process_->readAllStandardError()).trimmed()); });
  connect(process_, &QProcess::readyReadStandardOutput,
          [this] { log_->appendPlainText(QString::fromLocal8Bit(process_->readAllStandardOutput()).trimmed()); });
  connect(process_, QOverload<int, QProcess::ExitStatus>::of(&QProcess::finished),
          [this](int code, QProcess::ExitStatus status) {
            const bool ok = !cancelled_ && status == QProcess::NormalExit && code == 0;
            busy_->setRange(0, 1);
            busy_->setValue(ok ? 1 : 0);
            status_->setText(cancelled_ ? "cancelled: nothing was written"
                             : ok       ? "fitted: " + out_
                                        : QString("the fit failed (exit code %1)").arg(code));
            cancel_->setText("Close");
            if (done_)
              done_(ok);
          });
  connect(process_, &QProcess::errorOccurred, [this](QProcess::ProcessError e) {
    if (e == QProcess::FailedToStart) {
      status_->setText("cannot run " + program_);
      cancel_->setText("Close");
      if (done_)
        done_(false);
    }
  });
}

FitDialog::~FitDialog()
{
  if (running()) {
    cancelled_ = true;
    process_->kill();
    process_->waitForFinished(5000);
  }
}

void FitDialog::start()
{
  cancelled_ = false;
  process_->start(program_, {"fit", scan_, "-o", out_});
}

void FitDialog::cancel()
{
  if (!running())
    return;
  cancelled_ = true;
  process_->kill(); // the project is written atomically: a killed fit leaves none
}

bool FitDialog::running() const { return process_->state() != QProcess::NotRunning; }

QString FitDialog::log() const { return log_->toPlainText(); }

} // namespace meshpaint::studio
