#include "library_messages.h"

#include <OpenMesh/Core/System/omstream.hh> // for omerr, omlog, omout
#include <vtkLogger.h>                      // for vtkLogger
#include <vtkObjectFactory.h>               // for vtkStandardNewMacro
#include <vtkOutputWindow.h>                // for vtkOutputWindow
#include <vtkSmartPointer.h>                // for vtkSmartPointer

#include <cstdlib>  // for std::getenv
#include <cstring>  // for std::strcmp
#include <iostream> // for std::cerr, std::cout, std::clog

namespace meshpaint::cli {
namespace {

//! An output window that shows nothing: what VTK reports, our checks have
//! already turned into one line (or the result is checked after the call).
class vtkSilentOutputWindow : public vtkOutputWindow
{
public:
  static vtkSilentOutputWindow* New();
  vtkTypeMacro(vtkSilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char*) override {}
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}

protected:
  vtkSilentOutputWindow() = default;
};

vtkStandardNewMacro(vtkSilentOutputWindow);

//! Where OpenMesh's messages go instead: a stream without a buffer drops
//! everything written to it.
std::ostream& dropped()
{
  static std::ostream sink(nullptr);
  return sink;
}

} // namespace

void capture_library_messages()
{
  static bool done = false;
  const char* keep = std::getenv("MESHPAINT_LIBRARY_MESSAGES");
  if (done || (keep && std::strcmp(keep, "1") == 0))
    return;
  done = true;
  vtkOutputWindow::SetInstance(vtkSmartPointer<vtkSilentOutputWindow>::New());
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK's log, which some messages reach directly
  for (OpenMesh::mostream* stream : {&omerr(), &omlog(), &omout()}) {
    stream->disconnect(std::cerr);
    stream->disconnect(std::cout);
    stream->disconnect(std::clog);
    stream->connect(dropped());
  }
}

} // namespace meshpaint::cli
