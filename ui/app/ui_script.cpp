#include "ui/app/ui_script.h"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"

namespace rockface::ui {

namespace {

Eigen::Vector2f point(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    throw InputError(where, "expected a pixel [x, y]");
  return {j[0].get<float>(), j[1].get<float>()};
}

ScriptStep parse_step(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where, "a step is an object");
  ScriptStep s;
  if (j.contains("tap")) {
    s.kind = ScriptStep::Kind::tap;
    if (j["tap"].is_string())
      s.label = j["tap"].get<std::string>();
    else
      s.points = {point(j["tap"], where + ".tap")};
  } else if (j.contains("drag")) {
    s.kind = ScriptStep::Kind::drag;
    const auto& d = j["drag"];
    if (!d.is_array() || d.size() != 2)
      throw InputError(where + ".drag", "expected [[x, y], [x, y]]");
    s.points = {point(d[0], where + ".drag[0]"), point(d[1], where + ".drag[1]")};
    s.frames = j.value("frames", 8);
  } else if (j.contains("pinch")) {
    s.kind = ScriptStep::Kind::pinch;
    const auto& p = j["pinch"];
    if (!p.is_object() || !p.contains("centre"))
      throw InputError(where + ".pinch", "expected {centre, from, to}");
    s.points = {point(p["centre"], where + ".pinch.centre")};
    s.pinch_from = p.value("from", 100.0f);
    s.pinch_to = p.value("to", 200.0f);
    if (s.pinch_from <= 0 || s.pinch_to <= 0)
      throw InputError(where + ".pinch", "from and to are finger spreads in pixels, > 0");
    s.frames = j.value("frames", 8);
  } else if (j.contains("wait")) {
    if (j["wait"] != "task") throw InputError(where + ".wait", "only \"task\" can be waited for");
    s.kind = ScriptStep::Kind::wait_task;
  } else if (j.contains("frames")) {
    s.kind = ScriptStep::Kind::frames;
    if (!j["frames"].is_number_integer() || j["frames"].get<int>() < 1)
      throw InputError(where + ".frames", "a number of frames >= 1");
    s.frames = j["frames"].get<int>();
  } else if (j.contains("screenshot")) {
    s.kind = ScriptStep::Kind::screenshot;
    if (!j["screenshot"].is_string() || j["screenshot"].get<std::string>().empty())
      throw InputError(where + ".screenshot", "a file name (without .png)");
    s.label = j["screenshot"].get<std::string>();
    if (s.label.find('/') != std::string::npos)
      throw InputError(where + ".screenshot", "a name, not a path");
  } else {
    throw InputError(where, "unknown step (tap, drag, pinch, wait, frames, screenshot)");
  }
  return s;
}

}  // namespace

UiScript parse_ui_script(const std::string& text, const std::string& source) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(source, "not a JSON object");
  UiScript script;
  if (j.contains("viewport")) {
    const Eigen::Vector2f v = point(j["viewport"], source + ": viewport");
    script.width = static_cast<int>(v.x());
    script.height = static_cast<int>(v.y());
    if (script.width < 64 || script.height < 64 || script.width > 8192 || script.height > 8192)
      throw InputError(source, "viewport: each side from 64 to 8192 pixels");
  }
  if (!j.contains("steps") || !j["steps"].is_array())
    throw InputError(source, "steps: expected an array of steps");
  for (std::size_t i = 0; i < j["steps"].size(); ++i)
    script.steps.push_back(
        parse_step(j["steps"][i], source + ": steps[" + std::to_string(i) + "]"));
  return script;
}

UiScript load_ui_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_ui_script(text.str(), file.string());
}

}  // namespace rockface::ui
