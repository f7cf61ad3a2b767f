// Progress: how far long work has got, reported to whoever shows it. The
// engine never prints; the command line draws a bar or plain lines from these
// calls (app/progress_bar.h), and a caller that wants nothing passes none.
#pragma once

#include <cstddef> // for std::size_t
#include <string>  // for std::string

namespace meshpaint {

//! Receives the tasks of long work, one at a time.
class Progress
{
public:
  virtual ~Progress() = default;
  //! A task `what` of `total` steps begins (total at least 1).
  virtual void begin(const std::string& what, std::size_t total) = 0;
  //! `done` of the current task's steps are finished (at most total).
  virtual void step(std::size_t done) = 0;
  //! The current task is over, finished or not.
  virtual void end() = 0;
  //! A line about the work between tasks ("decimating to 2,000 faces").
  virtual void note(const std::string& line) = 0;
};

//! One task on an optional Progress: begin() now, end() when it goes out of
//! scope (also when an exception leaves it).
class ProgressTask
{
public:
  ProgressTask(Progress* progress, const std::string& what, std::size_t total) : progress_(progress)
  {
    if (progress_)
      progress_->begin(what, total == 0 ? 1 : total);
  }
  ~ProgressTask()
  {
    if (progress_)
      progress_->end();
  }
  ProgressTask(const ProgressTask&) = delete;
  ProgressTask& operator=(const ProgressTask&) = delete;

  void step(std::size_t done)
  {
    if (progress_)
      progress_->step(done);
  }

private:
  Progress* progress_;
};

//! A note on an optional Progress.
inline void note(Progress* progress, const std::string& line)
{
  if (progress)
    progress->note(line);
}

} // namespace meshpaint
