// Stopping long work from another thread: the interface sets a flag, the
// work looks at it at its step boundaries (between objects, strokes, files)
// and leaves by throwing Cancelled, so that everything it made unwinds as on
// any error (atomic writes remove their temporaries, see atomic_file.h).
#pragma once

#include <atomic>    // for std::atomic
#include <stdexcept> // for std::runtime_error

namespace meshpaint {

//! The flag a caller sets to ask work to stop; null where nobody can.
using CancelFlag = const std::atomic<bool>*;

//! The work stopped because it was asked to: nothing it would have written
//! was written.
class Cancelled : public std::runtime_error
{
public:
  Cancelled() : std::runtime_error("cancelled") {}
};

//! A step boundary. \throw Cancelled when `cancel` is set.
inline void stop_if_cancelled(CancelFlag cancel)
{
  if (cancel && cancel->load())
    throw Cancelled();
}

} // namespace meshpaint
