#include "progress_bar.h"

#include "core/format.h"

#include <algorithm> // for std::min
#include <cstdio>    // for std::snprintf
#include <cstdlib>   // for std::getenv
#include <cstring>   // for std::strcmp
#include <iostream>  // for std::cerr, std::ostream
#include <unistd.h>  // for isatty, STDERR_FILENO

namespace meshpaint::cli {
namespace {

constexpr int kBarWidth = 30;          // characters between the brackets
constexpr double kBarRedrawMs = 100.0; // a terminal redraw at most this often
constexpr double kLineMs = 1000.0;     // a plain line at most this often

ProgressBar::Mode chosen_mode(bool quiet)
{
  if (quiet)
    return ProgressBar::Mode::Quiet;
  const char* term = std::getenv("TERM");
  const bool dumb = term && std::strcmp(term, "dumb") == 0;
  return isatty(STDERR_FILENO) && !dumb ? ProgressBar::Mode::Bar : ProgressBar::Mode::Lines;
}

} // namespace

std::string clock_text(double seconds)
{
  const long s = seconds < 0 ? 0 : long(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

ProgressBar::ProgressBar(std::string prefix, bool quiet) : ProgressBar(std::move(prefix), chosen_mode(quiet), std::cerr)
{
}

ProgressBar::ProgressBar(std::string prefix, Mode mode, std::ostream& out)
  : prefix_(std::move(prefix)), mode_(mode), out_(out)
{
}

ProgressBar::~ProgressBar() { erase(); }

void ProgressBar::begin(const std::string& what, std::size_t total)
{
  erase();
  what_ = what;
  total_ = std::max<std::size_t>(total, 1);
  done_ = 0;
  active_ = true;
  task_.restart();
  shown_.restart();
  if (mode_ == Mode::Bar)
    draw();
}

void ProgressBar::step(std::size_t done)
{
  if (!active_)
    return;
  done_ = std::min(done, total_);
  if (mode_ == Mode::Bar && shown_.ms() >= kBarRedrawMs) {
    draw();
  } else if (mode_ == Mode::Lines && shown_.ms() >= kLineMs && done_ < total_) {
    const double seconds = task_.ms() / 1000.0;
    const double left = done_ > 0 ? seconds * double(total_ - done_) / double(done_) : -1;
    out_ << prefix_ << ": " << what_ << ": " << 100 * done_ / total_ << "%"
         << (left >= 0 ? " (" + clock_text(left) + " left)" : std::string()) << "\n";
    out_.flush();
    shown_.restart();
  }
}

void ProgressBar::end()
{
  if (!active_)
    return;
  active_ = false;
  const bool finished = done_ >= total_;
  // A task cut short by an error leaves no line behind: the error's is the one.
  if (mode_ == Mode::Bar && finished) {
    out_ << "\r" << prefix_ << ": " << what_ << ": 100% (" << format_fixed(task_.ms() / 1000.0, 1)
         << " s)\x1b[K\n";
    out_.flush();
    drawn_ = false;
  } else if (mode_ == Mode::Lines && finished) {
    out_ << prefix_ << ": " << what_ << ": 100% (" << format_fixed(task_.ms() / 1000.0, 1) << " s)\n";
    out_.flush();
  }
  erase();
}

void ProgressBar::note(const std::string& line)
{
  if (mode_ != Mode::Quiet)
    print(prefix_ + ": " + line);
}

void ProgressBar::print(const std::string& line)
{
  erase();
  out_ << line << "\n";
  out_.flush();
  if (active_ && mode_ == Mode::Bar)
    draw();
}

void ProgressBar::draw()
{
  const int filled = int(kBarWidth * done_ / total_);
  const double seconds = task_.ms() / 1000.0;
  std::string left = "--:-- left";
  if (done_ > 0 && seconds > 0.5)
    left = clock_text(seconds * double(total_ - done_) / double(done_)) + " left";
  out_ << "\r" << prefix_ << ": " << what_ << " [" << std::string(std::size_t(filled), '#')
       << std::string(std::size_t(kBarWidth - filled), '.') << "] " << 100 * done_ / total_ << "% " << left
       << "\x1b[K";
  out_.flush();
  drawn_ = true;
  shown_.restart();
}

void ProgressBar::erase()
{
  if (!drawn_)
    return;
  out_ << "\r\x1b[K";
  out_.flush();
  drawn_ = false;
}

} // namespace meshpaint::cli
