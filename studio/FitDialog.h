// The studio's fit dialog: `meshpaint fit SCAN -o PROJECT` run as a child
// process, off the interface thread, its progress lines shown as they come
// and Cancel stopping it.
#pragma once

#include <QDialog> // for QDialog
#include <QString> // for QString

#include <functional> // for std::function

class QLabel;
class QPlainTextEdit;
class QProcess;
class QProgressBar;
class QPushButton;

namespace meshpaint::studio {

class FitDialog : public QDialog
{
public:
  //! Fits `scan` into the project `out` with the `meshpaint` executable
  //! `program`; `done` hears how it ended (true: `out` was written).
  FitDialog(const QString& program, const QString& scan, const QString& out, std::function<void(bool)> done,
            QWidget* parent = nullptr);
  ~FitDialog() override;
  //! Starts the fit (returns at once).
  void start();
  //! Stops a running fit; nothing is written.
  void cancel();
  bool running() const;
  //! What the fit printed so far.
  QString log() const;

private:
  //! Adds `text` read from one of the fit's streams to the unfinished line
  //! `part` of that stream; each line it finishes goes into the log.
  void take(QString& part, const QString& text);

  QString error_part_, output_part_;
  QString program_, scan_, out_;
  std::function<void(bool)> done_;
  QProcess* process_;
  QLabel* status_;
  QProgressBar* busy_;
  QPlainTextEdit* log_;
  QPushButton* cancel_;
  bool cancelled_ = false;
};

} // namespace meshpaint::studio
