// What a project's content must satisfy beyond its checksums: finite values
// in their ranges, a base mesh that needs no repair, valid label classes.
#pragma once

#include "mesh/channel_arrays.h" // for meshpaint::channel_value_problem
#include "project/project.h"

#include <string> // for std::string

namespace meshpaint {

//! Checks what load_project() read: the base mesh as make_base_mesh() would
//! take it without a repair, control points finite and within
//! kMaxCoordinate, every channel value as channel_value_problem() allows,
//! labels as check_labels(), the history within kMaxStrokeScriptBytes.
//! \throw InputError "corrupt project (...)" naming the first problem.
void check_project_content(const Project& project, const std::string& where);

} // namespace meshpaint
