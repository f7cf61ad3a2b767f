// QuietOpenMesh: silences OpenMesh's console messages while it reads or
// writes; our own errors say what went wrong, in one line.
#pragma once

#include <OpenMesh/Core/System/omstream.hh> // for omerr, omlog, omout

namespace meshpaint {

//! Disables OpenMesh's omerr, omlog and omout for its lifetime.
class QuietOpenMesh
{
public:
  QuietOpenMesh()
  {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh()
  {
    omerr().enable();
    omlog().enable();
    omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;
};

} // namespace meshpaint
