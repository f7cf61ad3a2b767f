#include "project/labels.h"

#include "core/errors.h"

#include <nlohmann/json.hpp> // for nlohmann::json

#include <cmath>   // for std::isfinite
#include <fstream> // for std::ifstream
#include <set>     // for std::set
#include <sstream> // for std::ostringstream

namespace meshpaint {

std::vector<LabelClass> parse_labels(const std::string& json_text)
{
  using nlohmann::json;
  json j;
  try {
    j = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw InputError(std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_array())
    throw InputError("labels must be a JSON array of {\"id\", \"name\", \"colour\"} objects");
  std::vector<LabelClass> labels;
  std::set<int> ids;
  std::set<std::string> names;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const json& e = j[k];
    const std::string where = "label " + std::to_string(k) + ": ";
    if (!e.is_object())
      throw InputError(where + "must be an object with \"id\", \"name\" and \"colour\"");
    for (const auto& item : e.items())
      if (item.key() != "id" && item.key() != "name" && item.key() != "colour")
        throw InputError(where + "unknown key \"" + item.key() + "\" (id, name, colour)");
    LabelClass c;
    if (!e.contains("id") || !e["id"].is_number_integer() || e["id"].get<long long>() < 0 ||
        e["id"].get<long long>() > kMaxLabelId)
      throw InputError(where + "\"id\" must be an integer from 0 to " + std::to_string(kMaxLabelId));
    c.id = e["id"].get<int>();
    if (!e.contains("name") || !e["name"].is_string() || e["name"].get<std::string>().empty())
      throw InputError(where + "\"name\" must be a non-empty string");
    c.name = e["name"].get<std::string>();
    const bool colour_ok = e.contains("colour") && e["colour"].is_array() && e["colour"].size() == 3;
    for (int a = 0; a < 3 && colour_ok; ++a) {
      const json& v = e["colour"][std::size_t(a)];
      if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1.0))
        throw InputError(where + "\"colour\" must be [r, g, b] with numbers from 0 to 1");
      c.colour[std::size_t(a)] = v.get<float>();
    }
    if (!colour_ok)
      throw InputError(where + "\"colour\" must be [r, g, b] with numbers from 0 to 1");
    if (!ids.insert(c.id).second)
      throw InputError(where + "id " + std::to_string(c.id) + " is used twice");
    if (!names.insert(c.name).second)
      throw InputError(where + "name \"" + c.name + "\" is used twice");
    labels.push_back(c);
  }
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
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw IOError("cannot read labels '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parse_labels(text.str());
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

} // namespace meshpaint
