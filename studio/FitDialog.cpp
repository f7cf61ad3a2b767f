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
  // Progress comes on stderr, one line per step; the report on stdout. Each
  // read brings whatever the pipe holds, parts of lines too: whole lines go
  // into the log.
  connect(process_, &QProcess::readyReadStandardError,
          [this] { take(error_part_, QString::fromLocal8Bit(process_->readAllStandardError())); });
  connect(process_, &QProcess::readyReadStandardOutput,
          [this] { take(output_part_, QString::fromLocal8Bit(process_->readAllStandardOutput())); });
  connect(process_, QOverload<int, QProcess::ExitStatus>::of(&QProcess::finished),
          [this](int code, QProcess::ExitStatus status) {
            for (QString* part : {&error_part_, &output_part_}) // a last line without its newline
              take(*part, part->isEmpty() ? QString() : "\n");
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

void FitDialog::take(QString& part, const QString& text)
{
  part += text;
  int end;
  while ((end = part.indexOf('\n')) >= 0) {
    // A terminal's progress bar redraws its line after carriage returns: the last drawing stands.
    const QStringList drawings = part.left(end).split('\r', Qt::SkipEmptyParts);
    QString line = drawings.isEmpty() ? QString() : drawings.back();
    line.remove("\x1b[K"); // "clear to the end of the line"
    part.remove(0, end + 1);
    if (!line.trimmed().isEmpty())
      log_->appendPlainText(line.trimmed());
  }
}

QString FitDialog::log() const { return log_->toPlainText(); }

} // namespace meshpaint::studio
