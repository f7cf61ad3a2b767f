// Named label classes: what the integers of the label channel stand for.
#pragma once

#include "core/vec.h"
#include "mesh/channel_arrays.h" // for meshpaint::kMaxLabelId

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! One class of the label channel.
struct LabelClass
{
  int id = 0;       //!< the value painted into the label channel
  std::string name; //!< unique, not empty
  Vec3 colour{};    //!< rgb, 0..1
};

//! Checks label classes however they were read (a labels file, a project):
//! ids 0..kMaxLabelId, names not empty and valid UTF-8, colours 0..1, ids
//! and names unique.
//! \throw InputError naming the entry (0-based) and key.
void check_labels(const std::vector<LabelClass>& labels);

//! Parses a labels file: a JSON array of {"id": int, "name": text,
//! "colour": [r, g, b]} (0..1), ids and names unique.
//! \throw InputError naming the entry (0-based) and key.
std::vector<LabelClass> parse_labels(const std::string& json_text);

//! The labels file of `labels` (parse_labels() reads it back equal).
std::string labels_json(const std::vector<LabelClass>& labels);

//! Reads and parses a labels file (a regular file of at most
//! kMaxLabelTableBytes); errors start with the path.
//! \throw IOError when the file cannot be read; InputError as above.
std::vector<LabelClass> load_labels(const std::string& path);

} // namespace meshpaint
