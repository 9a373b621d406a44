#include "storage/scene/camera_json.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "storage/json_reader.h"

namespace rockface::storage {

using json = nlohmann::json;
using photogrammetry::CameraIntrinsics;

namespace {

constexpr const char* kFormat = "rockface-camera/1";
constexpr const char* kModel = "opencv-brown";

struct Fields {
  const json& doc;
  const std::string& source;

  [[noreturn]] void fail(const std::string& field, const std::string& reason) const {
    throw InputError(source + ": " + field, reason);
  }
  const json& require(const char* key) const {
    auto it = doc.find(key);
    if (it == doc.end()) fail(key, "missing");
    return *it;
  }
  double number(const json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "must be a number, not " + v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(field, "must be finite");
    return d;
  }
  double positive(const char* key) const {
    const double d = number(require(key), key);
    if (!(d > 0)) fail(key, require(key).dump() + " must be positive");
    return d;
  }
  int size(const char* key) const {
    const json& v = require(key);
    if (!v.is_number_integer()) fail(key, "must be a whole number of pixels, not " + v.dump());
    const auto n = v.get<long long>();
    if (n < 1 || n > 100000) fail(key, v.dump() + " is not an image size in pixels");
    return static_cast<int>(n);
  }
  std::string text(const char* key) const {
    auto it = doc.find(key);
    if (it == doc.end() || it->is_null()) return {};
    if (!it->is_string()) fail(key, "must be a string");
    return it->get<std::string>();
  }
};

}  // namespace

CameraIntrinsics parse_camera_json(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::out_of_range&) {
    throw_number_overflow(text, source);
  } catch (const json::exception& e) {
    // nlohmann's message carries the byte position of the fault. Also a
    // number beyond double's range (1e309), found by tests/storage/fuzz.
    throw InputError(source, std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object()) throw InputError(source, "must hold a JSON object");
  const Fields f{doc, source};
  const json& format = f.require("format");
  if (!format.is_string() || format.get<std::string>() != kFormat)
    f.fail("format", format.dump() + " is not \"" + kFormat + "\"");
  if (auto it = doc.find("model"); it != doc.end() && *it != kModel)
    f.fail("model", it->dump() + " is not \"" + std::string(kModel) +
                        "\" (the only camera model rockface reads)");
  CameraIntrinsics c;
  c.width = f.size("width");
  c.height = f.size("height");
  c.fx = f.positive("fx");
  c.fy = f.positive("fy");
  c.cx = f.number(f.require("cx"), "cx");
  c.cy = f.number(f.require("cy"), "cy");
  if (c.cx < -0.5 || c.cx > c.width - 0.5) f.fail("cx", "lies outside the image width");
  if (c.cy < -0.5 || c.cy > c.height - 0.5) f.fail("cy", "lies outside the image height");
  const json& d = f.require("distortion");
  if (!d.is_array() || d.size() != 5)
    f.fail("distortion", "must be an array of 5 numbers [k1, k2, p1, p2, k3]");
  for (size_t k = 0; k < 5; ++k)
    c.distortion[k] = f.number(d[k], "distortion[" + std::to_string(k) + "]");
  if (auto it = doc.find("rms_px"); it != doc.end()) {
    c.rms_px = f.number(*it, "rms_px");
    if (c.rms_px < 0) f.fail("rms_px", "must not be negative");
  }
  c.body = f.text("body");
  c.lens = f.text("lens");
  c.focus = f.text("focus");
  return c;
}

CameraIntrinsics load_camera_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot be opened");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_camera_json(buffer.str(), path);
}

std::string camera_json_text(const CameraIntrinsics& c) {
  json doc = json::object();
  doc["format"] = kFormat;
  doc["model"] = kModel;
  doc["width"] = c.width;
  doc["height"] = c.height;
  doc["fx"] = c.fx;
  doc["fy"] = c.fy;
  doc["cx"] = c.cx;
  doc["cy"] = c.cy;
  doc["distortion"] = std::vector<double>(c.distortion.begin(), c.distortion.end());
  doc["rms_px"] = c.rms_px;
  if (!c.body.empty()) doc["body"] = c.body;
  if (!c.lens.empty()) doc["lens"] = c.lens;
  if (!c.focus.empty()) doc["focus"] = c.focus;
  return doc.dump(2) + "\n";
}

void save_camera_json(const std::string& path, const CameraIntrinsics& camera) {
  const std::string text = camera_json_text(camera);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace rockface::storage
