// The stroke-script schema against what uses it: the reference in
// docs/strokes.md lists exactly its keys, the parser refuses a key for the
// tools the schema leaves out, and the writer writes only its keys.

#include "paint/stroke_schema.h"

#include <nlohmann/json.hpp> // for nlohmann::json

#include <gtest/gtest.h>

#include <fstream> // for std::ifstream
#include <set>     // for std::set
#include <string>  // for std::string

namespace meshpaint {
namespace {

using nlohmann::json;

//! The keys named in the first column of the first table after `heading`
//! in docs/strokes.md (a row may name several: "`lambda`, `mu`").
std::set<std::string> documented_keys(const std::string& heading)
{
  std::ifstream in(std::string(MESHPAINT_SOURCE_DIR) + "/docs/strokes.md");
  EXPECT_TRUE(in) << "docs/strokes.md";
  std::set<std::string> keys;
  std::string line;
  bool in_section = false, in_table = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0)
      in_section = line == heading;
    if (!in_section)
      continue;
    if (line.rfind("| `", 0) != 0) {
      if (in_table)
        break;
      continue;
    }
    in_table = true;
    const std::string cell = line.substr(1, line.find('|', 1) - 1);
    for (std::size_t at = cell.find('`'); at != std::string::npos; at = cell.find('`', cell.find('`', at + 1) + 1))
      keys.insert(cell.substr(at + 1, cell.find('`', at + 1) - at - 1));
  }
  return keys;
}

std::set<std::string> names(const std::vector<StrokeKey>& keys)
{
  std::set<std::string> out;
  for (const StrokeKey& k : keys)
    out.insert(k.name);
  return out;
}

TEST(StrokeSchema, TheReferenceListsEveryKeyAndNoOther)
{
  EXPECT_EQ(documented_keys("## Stroke keys"), names(stroke_keys()));
  EXPECT_EQ(documented_keys("## Pattern paint"), names(pattern_keys()));
}

//! A valid stroke of each tool with the fewest keys.
json minimal_stroke(Tool tool)
{
  json s = {{"tool", tool_name(tool)}};
  if (!covers_everything(tool))
    s.update({{"points", {{0, 0, 0}}}, {"radius", 1}});
  if (tool == Tool::Paint || tool == Tool::Wash || tool == Tool::Dip)
    s["channels"] = {{"diffuse", {1, 0, 0}}};
  if (tool == Tool::Label || tool == Tool::Fill || tool == Tool::Merge)
    s["channels"] = {{"label", 1}};
  if (tool == Tool::Merge)
    s["only_over_label"] = 2;
  if (tool == Tool::Dip)
    s["pattern"] = {{"type", "bath"}};
  if (tool == Tool::Sculpt || tool == Tool::Inflate)
    s["amount"] = 0.1;
  return s;
}

//! A value each key accepts on its own.
const json kValues = {{"tool", "paint"},
                      {"points", {{0, 0, 0}}},
                      {"radius", 1},
                      {"strength", 0.5},
                      {"falloff", "linear"},
                      {"spacing", 0.5},
                      {"op", "over"},
                      {"channels", {{"diffuse", {1, 0, 0}}}},
                      {"alphas", {{"diffuse", 0.5}}},
                      {"pressure", {1}},
                      {"mirror", "x"},
                      {"amount", 0.1},
                      {"iterations", 2},
                      {"target", "color"},
                      {"method", "laplacian"},
                      {"lambda", 0.5},
                      {"mu", -0.6},
                      {"mode", "dye"},
                      {"coefficient", 0.5},
                      {"pattern", {{"type", "noise"}}},
                      {"stroke", "rubberstamp"},
                      {"stamp", "brush.png"},
                      {"edit_level", 1},
                      {"space", "tangent"},
                      {"camera", {{"position", {0, 0, 5}}, {"focal_point", {0, 0, 0}}, {"view_up", {0, 1, 0}}}},
                      {"backfaces", "paint"},
                      {"spray", {{"drops", 4}, {"size", 0.1}}},
                      {"side", "outside"},
                      {"locked_labels", {2}},
                      {"only_over_label", 0},
                      {"connect", "diagonals"}};

TEST(StrokeSchema, TheParserRefusesAKeyForTheToolsTheSchemaLeavesOut)
{
  for (const std::string& tool_text : key_names(stroke_key("tool"))) {
    const Tool tool = tool_named(tool_text);
    const json base = minimal_stroke(tool);
    ASSERT_NO_THROW(parse_stroke_script(json{{"strokes", {base}}}.dump())) << tool_text;
    for (const StrokeKey& key : stroke_keys()) {
      ASSERT_TRUE(kValues.contains(key.name)) << key.name;
      if (applies_to(key, tool))
        continue;
      json s = base;
      s[key.name] = kValues[key.name];
      try {
        parse_stroke_script(json{{"strokes", {s}}}.dump());
        ADD_FAILURE() << "a " << tool_text << " stroke takes \"" << key.name << "\"";
      } catch (const StrokeKeyError& e) {
        EXPECT_EQ(e.key(), key.name) << e.what();
      }
    }
  }
}

TEST(StrokeSchema, BrushKeysOfOtherToolsAreDropped)
{
  for (const std::string& tool_text : key_names(stroke_key("tool"))) {
    json s = minimal_stroke(tool_named(tool_text));
    for (const StrokeKey& key : stroke_keys())
      if (!applies_to(key, tool_named(tool_text)))
        s[key.name] = kValues[key.name];
    const json kept = json::parse(drop_meaningless_keys(s.dump()));
    EXPECT_EQ(kept, minimal_stroke(tool_named(tool_text))) << tool_text;
  }
}

TEST(StrokeSchema, TheWriterWritesOnlySchemaKeys)
{
  const StrokeScript script = parse_stroke_script(R"({"strokes": [
    {"tool": "paint", "points": [[0, 0, 1], [1, 0, 0]], "radius": 0.3, "falloff": "gaussian", "op": "over",
     "channels": {"diffuse": [0.9, 0.2, 0.1]}, "pressure": [0.5, 1], "mirror": "y", "space": "screen",
     "camera": {"position": [0, 0, 5], "focal_point": [0, 0, 0], "view_up": [0, 1, 0]}, "backfaces": "paint",
     "spray": {"drops": 3, "size": 0.01}, "side": "inside", "stamp": "brush.png",
     "pattern": {"type": "image", "file": "p.png", "coord": "uv", "matte": "opaque"}},
    {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "mode": "polish", "coefficient": 0.8},
    {"tool": "smooth", "points": [[0, 0, 1]], "radius": 0.2, "iterations": 3, "method": "laplacian",
     "edit_level": 2},
    {"tool": "smooth", "points": [[0, 0, 1]], "radius": 0.2, "target": "color"},
    {"tool": "sculpt", "points": [[0, 0, 1]], "radius": 0.2, "amount": -0.1},
    {"tool": "dip", "channels": {"label": 3}, "pattern": {"type": "bath"}}]})");
  const json written = json::parse(stroke_script_json(script));
  for (const json& stroke : written["strokes"])
    for (const auto& item : stroke.items()) {
      EXPECT_EQ(names(stroke_keys()).count(item.key()), 1u) << item.key();
      if (item.key() == "pattern")
        for (const auto& p : item.value().items())
          EXPECT_EQ(names(pattern_keys()).count(p.key()), 1u) << p.key();
    }
}

TEST(StrokeSchema, WordNamesStandForDistinctValues)
{
  for (const StrokeKey& key : stroke_keys())
    for (std::size_t a = 0; a < key.names.size(); ++a)
      for (std::size_t b = a + 1; b < key.names.size(); ++b)
        if (key.names[a].value >= 0)
          EXPECT_NE(key.names[a].value, key.names[b].value) << key.name;
}

} // namespace
} // namespace meshpaint
