// Messages that VTK and OpenMesh print on their own: the command line keeps
// them off the terminal, since every failure is already reported as one line
// of ours (docs/cli.md, "Errors and exit codes").
#pragma once

namespace meshpaint::cli {

//! Routes VTK's output window and OpenMesh's omerr, omlog and omout away
//! from stderr and stdout for the rest of the process, unless
//! MESHPAINT_LIBRARY_MESSAGES is 1 (for looking into a failure).
void capture_library_messages();

} // namespace meshpaint::cli
