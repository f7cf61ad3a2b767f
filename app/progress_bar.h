// ProgressBar: how the command line shows the engine's Progress: a bar with
// the percentage and the time left when stderr is a terminal, plain lines
// when it is not, nothing with --quiet.
#pragma once

#include "core/progress.h"
#include "core/timer.h"

#include <iosfwd> // for std::ostream
#include <string> // for std::string

namespace meshpaint::cli {

class ProgressBar : public Progress
{
public:
  enum class Mode
  {
    Bar,   //!< one line redrawn in place
    Lines, //!< a line at most every second, and one when a task finishes
    Quiet  //!< nothing
  };

  //! Shows on stderr, each line starting "PREFIX: " (e.g. "meshpaint fit");
  //! Quiet when `quiet`, else Bar when stderr is a terminal (and TERM is not
  //! "dumb"), else Lines.
  ProgressBar(std::string prefix, bool quiet);
  ProgressBar(std::string prefix, Mode mode, std::ostream& out);
  ~ProgressBar() override;
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void begin(const std::string& what, std::size_t total) override;
  void step(std::size_t done) override;
  void end() override;
  void note(const std::string& line) override;

  //! Writes `line` as it is (a warning), taking a drawn bar off first; also
  //! when quiet.
  void print(const std::string& line);

  Mode mode() const { return mode_; }

private:
  void draw();
  void erase();

  std::string prefix_;
  Mode mode_;
  std::ostream& out_;
  std::string what_;
  std::size_t total_ = 0;
  std::size_t done_ = 0;
  bool active_ = false;
  bool drawn_ = false; //!< a bar is on the terminal's current line
  Timer task_;         //!< since begin()
  Timer shown_;        //!< since the last bar or line
};

//! "0:42", "12:05", "1:02:03" for a duration in seconds.
std::string clock_text(double seconds);

} // namespace meshpaint::cli
