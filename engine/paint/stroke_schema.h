// The stroke-script schema: every key a stroke may have, its JSON type, its
// range or names, the tools it means something for, its default and the
// member it sets. The parser, the writer, the window's brush and the Python
// setters all take keys, names and ranges from here.
#pragma once

#include "paint/stroke.h" // for meshpaint::Tool, meshpaint::Stroke

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! What JSON a key takes.
enum class KeyType
{
  Number,  //!< a finite number within [min, max]
  Integer, //!< an integer within [min, max]
  Word,    //!< one of `names`
  Points,  //!< [[x, y, z], ...]
  Numbers, //!< a list of numbers, one per point
  Ids,     //!< a list of integers within [min, max]
  Object,  //!< an object of sub-keys (channels, alphas, pattern, camera, spray)
  File     //!< a file name
};

//! A set of tools, one bit per enum Tool value.
using ToolSet = unsigned;
constexpr ToolSet tool_bit(Tool tool) { return 1u << unsigned(tool); }
//! Every tool.
constexpr ToolSet kAllTools = (1u << 13) - 1u;

//! One accepted name of a word key and the member value it stands for.
struct KeyName
{
  const char* name;
  int value; //!< e.g. FALLOFF_LINEAR; -1 where the name does not set the member
             //!< (op "blur": a tool)
};

//! One key of a stroke (or of one of its objects: "pattern").
struct StrokeKey
{
  const char* name;
  KeyType type;
  double min = 0, max = 0;    //!< Number, Integer: the accepted range
  std::vector<KeyName> names; //!< Word: the accepted names, in the order messages list them
  ToolSet tools = kAllTools;  //!< the tools it means something for (some keys
                              //!< depend on others too)
  const char* fallback = "";  //!< the default as a script writes it; "" none or required
  const char* member = "";    //!< what it sets, e.g. "Brush::radius"
};

//! The keys of a stroke, in the order "is not a stroke key" lists them.
const std::vector<StrokeKey>& stroke_keys();
//! The keys of a stroke's "pattern" object.
const std::vector<StrokeKey>& pattern_keys();
//! The key of that name among stroke_keys(). \throw std::logic_error for no
//! such key (a bug)
const StrokeKey& stroke_key(const std::string& name);
//! The key of that name among pattern_keys(). \throw std::logic_error for no
//! such key (a bug)
const StrokeKey& pattern_key(const std::string& name);

//! The key means something for the tool (stroke_keys() says for which).
inline bool applies_to(const StrokeKey& key, Tool tool) { return (key.tools & tool_bit(tool)) != 0; }

//! A word key's names, in order.
std::vector<std::string> key_names(const StrokeKey& key);
//! Words as messages list them: "a, b, c".
std::string join_names(const std::vector<std::string>& words);
//! A word key's names as messages list them: "a, b, c".
std::string name_list(const StrokeKey& key);
//! The keys' names as messages list them: "a, b, c".
std::string key_list(const std::vector<StrokeKey>& keys);
//! The name of a word key that stands for `value`. \throw std::logic_error for
//! none (a bug)
const char* name_of(const StrokeKey& key, int value);
//! The member value a word key's name stands for. \pre name is one of key.names
int value_of(const StrokeKey& key, const std::string& name);

//! Channel names of "channels" and "alphas", indexed by CHANNEL_*.
const std::vector<std::string>& channel_names();

} // namespace meshpaint
