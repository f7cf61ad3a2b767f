#include "project/labels.h"

#include "core/errors.h"
#include "core/format.h"     // for meshpaint::excerpt
#include "core/input_file.h" // for meshpaint::read_input_file

#include <nlohmann/json.hpp> // for nlohmann::json

#include <cmath>   // for std::isfinite
#include <set>     // for std::set

namespace meshpaint {

namespace {

const std::string kIdRule = "\"id\" must be an integer from 0 to " + std::to_string(kMaxLabelId);
const std::string kNameRule = "\"name\" must be a non-empty string";
const std::string kColourRule = "\"colour\" must be [r, g, b] with numbers from 0 to 1";

std::string label_where(std::size_t k)
{
  return "label " + std::to_string(k) + ": ";
}

} // namespace

void check_labels(const std::vector<LabelClass>& labels)
{
  std::set<int> ids;
  std::set<std::string> names;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const LabelClass& c = labels[k];
    const std::string where = label_where(k);
    if (c.id < 0 || c.id > kMaxLabelId)
      throw InputError(where + kIdRule);
    if (c.name.empty())
      throw InputError(where + kNameRule);
    if (!is_utf8(c.name))
      throw InputError(where + "\"name\" \"" + excerpt(c.name) + "\" is not valid UTF-8");
    for (const float x : c.colour)
      if (!(x >= 0.f && x <= 1.f))
        throw InputError(where + kColourRule);
    if (!ids.insert(c.id).second)
      throw InputError(where + "id " + std::to_string(c.id) + " is used twice");
    if (!names.insert(c.name).second)
      throw InputError(where + "name \"" + excerpt(c.name) + "\" is used twice");
  }
}

std::vector<LabelClass> parse_labels(const std::string& json_text)
{
  using nlohmann::json;
  json j;
  try {
    j = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw InputError("not valid JSON: " + excerpt(e.what(), kMessageChars));
  }
  if (!j.is_array())
    throw InputError("labels must be a JSON array of {\"id\", \"name\", \"colour\"} objects");
  std::vector<LabelClass> labels;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const json& e = j[k];
    const std::string where = label_where(k);
    if (!e.is_object())
      throw InputError(where + "must be an object with \"id\", \"name\" and \"colour\"");
    for (const auto& item : e.items())
      if (item.key() != "id" && item.key() != "name" && item.key() != "colour")
        throw InputError(where + "unknown key \"" + excerpt(item.key()) + "\" (id, name, colour)");
    LabelClass c;
    if (!e.contains("id") || !e["id"].is_number_integer() || e["id"].get<long long>() < 0 ||
        e["id"].get<long long>() > kMaxLabelId)
      throw InputError(where + kIdRule);
    c.id = e["id"].get<int>();
    if (!e.contains("name") || !e["name"].is_string())
      throw InputError(where + kNameRule);
    c.name = e["name"].get<std::string>();
    if (!e.contains("colour") || !e["colour"].is_array() || e["colour"].size() != 3)
      throw InputError(where + kColourRule);
    for (int a = 0; a < 3; ++a) {
      const json& v = e["colour"][std::size_t(a)];
      if (!v.is_number())
        throw InputError(where + kColourRule);
      // Checked as a double: a float rounding 1.0000001 down must not pass.
      if (!(v.get<double>() >= 0.0 && v.get<double>() <= 1.0))
        throw InputError(where + kColourRule);
      c.colour[std::size_t(a)] = v.get<float>();
    }
    labels.push_back(c);
  }
  check_labels(labels);
  return labels;
}

std::string labels_json(const std::vector<LabelClass>& labels)
{
  nlohmann::json j = nlohmann::json::array();
  for (const LabelClass& c : labels)
    j.push_back({{"id", c.id}, {"name", c.name}, {"colour", {c.colour[0], c.colour[1], c.colour[2]}}});
  return j.dump(1) + "\n";
}

std::vector<LabelClass> load_labels(const std::string& path)
{
  const std::string text = read_input_file(path, kMaxLabelTableBytes, "label table");
  try {
    return parse_labels(text);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

} // namespace meshpaint
