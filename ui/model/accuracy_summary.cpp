#include "ui/model/accuracy_summary.h"

#include <nlohmann/json.hpp>

#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

using nlohmann::json;
namespace f = format;

std::optional<double> number(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

std::string text_of(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_string()) return {};
  return j[key].get<std::string>();
}

void scale_and_orientation(std::vector<AccuracyLine>& out, const json& reg, const json& p) {
  const std::string scale = text_of(reg, "scale_source");
  if (scale == "range pole") {
    std::string v = "range pole";
    if (const auto* pole = reg.contains("range_pole") ? &reg["range_pole"] : nullptr)
      if (const auto l = number(*pole, "length_m"); l && *l > 0)
        v += ", " + f::text(f::Length{*l}) + " between its targets";
    out.push_back({"Scale", v});
  } else if (!scale.empty()) {
    out.push_back({"Scale", f::in_words(scale)});
  } else if (reg.is_object() && reg.value("scaled", true) == false) {
    out.push_back({"Scale", "not scaled: lengths are in units of the camera base", true});
  }
  if (const std::string v = text_of(reg, "vertical_source"); !v.empty())
    out.push_back({"Vertical", f::in_words(v)});
  if (reg.is_object() && reg.contains("north") && reg["north"].is_object()) {
    const json& n = reg["north"];
    std::string v = f::in_words(text_of(reg, "north_source"));
    if (const auto a = number(n, "azimuth_deg")) v += ", line at " + f::azimuth(*a);
    if (const auto d = number(n, "declination_deg"); d && *d != 0)
      v += ", declination " + f::text(f::Angle{*d});
    out.push_back({"North", v});
  } else if (const std::string v = text_of(reg, "north_source"); v == "none") {
    out.push_back({"North", "not oriented: no compass line was given for this pair", true});
  } else if (!v.empty()) {
    out.push_back({"North", f::in_words(v)});
  } else if (p.is_object() && p.contains("format")) {
    out.push_back({"North", "not oriented to north", true});
  }
}

void precision(std::vector<AccuracyLine>& out, const json& p) {
  if (const auto s = number(p, "predicted_depth_sigma_mm"))
    out.push_back(
        {"Point precision", f::plus_minus(f::Length{*s / 1000}) + " in depth (1σ, predicted)"});
  if (const auto d = number(p, "distance")) {
    std::string v = f::text(f::Length{*d});
    if (const auto b = number(p, "base")) {
      v += ", base " + f::text(f::Length{*b});
      if (const auto r = number(p, "base_to_distance")) v += " (" + f::one_in(*r) + ")";
    }
    out.push_back({"Distance to the face", v});
  }
  if (const auto s = number(p, "point_spacing"))
    out.push_back({"Point spacing", f::text(f::Length{*s})});
}

void matching(std::vector<AccuracyLine>& out, const json& p) {
  if (p.is_object() && p.contains("orientation") && p["orientation"].is_object()) {
    const json& o = p["orientation"];
    const auto inliers = number(o, "inliers"), matches = number(o, "matches");
    std::string v;
    if (inliers && matches)
      v = f::count(static_cast<std::int64_t>(*inliers)) + " of " +
          f::count(static_cast<std::int64_t>(*matches), "match", "matches") + " kept";
    if (const auto rms = number(o, "rms_reprojection_px"))
      v += (v.empty() ? "" : ", ") + f::pixels(*rms) + " reprojection (rms)";
    if (const auto c = number(o, "tie_point_coverage"))
      v += (v.empty() ? "" : ", ") + f::text(f::Fraction{*c}) + " of the image covered";
    if (!v.empty()) out.push_back({"Pair orientation", v});
  }
  if (p.is_object() && p.contains("dense") && p["dense"].is_object()) {
    const json& d = p["dense"];
    if (const auto valid = number(d, "valid_fraction")) {
      std::string v = f::text(f::Fraction{*valid}) + " of the pixels matched";
      if (const auto s = number(d, "image_scale"); s && *s < 0.999)
        v += ", at " + f::text(f::Fraction{*s}) + " of full resolution";
      out.push_back({"Surface matching", v});
    }
  }
}

void residual(std::vector<AccuracyLine>& out, const storage::Model& model, const json& reg) {
  // A residual needs redundancy: two pole targets fix the scale and the
  // vertical exactly and leave nothing over to check them against.
  const json* cp =
      reg.is_object() && reg.contains("control_points") ? &reg["control_points"] : nullptr;
  if (cp && cp->is_object() && model.residuals.size() >= 3) {
    std::string v = f::text(f::Length{model.registration.rms_m}) + " rms over " +
                    f::count(static_cast<std::int64_t>(model.residuals.size()), "control point",
                             "control points");
    const std::string worst = text_of(*cp, "worst");
    if (const auto w = number(*cp, "worst_m"); w && !worst.empty())
      v += ", worst " + worst + " " + f::text(f::Length{*w});
    out.push_back({"Residual", v});
  } else {
    const bool pole = reg.is_object() && reg.contains("range_pole");
    const std::int64_t n = pole ? 2 : static_cast<std::int64_t>(model.residuals.size());
    out.push_back({"Residual", "needs three or more targets (" +
                                   (n == 0 ? std::string("none here")
                                           : f::count(n, "target", "targets") + " here") +
                                   ": nothing over to check the scale against)"});
  }
}

void face_registration(std::vector<AccuracyLine>& out, const storage::Model& model, const json& p) {
  out.push_back({"Placed", "onto pair 1's 3D image (one face frame)"});
  if (p.is_object() && p.contains("images") && p["images"].is_array())
    for (const auto& i : p["images"]) {
      if (text_of(i, "role") != "registered") continue;
      std::string v;
      if (const auto t = number(i, "tie_points"))
        v = f::count(static_cast<std::int64_t>(*t), "tie point", "tie points");
      if (const auto r = number(i, "tie_point_rms_m"))
        v += (v.empty() ? "" : ", ") + f::text(f::Length{*r}) + " rms";
      if (const auto o = number(i, "overlap"))
        v += (v.empty() ? "" : ", ") + f::text(f::Fraction{*o}) + " overlap";
      if (!v.empty()) out.push_back({"Tie points (" + f::file_name(text_of(i, "name")) + ")", v});
    }
  out.push_back({"Surface fit",
                 f::text(f::Length{model.registration.rms_m}) + " rms against pair 1's surface"});
  if (const auto s = number(p, "predicted_depth_sigma_mm"))
    out.push_back(
        {"Point precision", f::plus_minus(f::Length{*s / 1000}) + " in depth (1σ, predicted)"});
}

}  // namespace

std::vector<AccuracyLine> accuracy_lines(const storage::Model& model) {
  std::vector<AccuracyLine> out;
  const std::string& text = model.registration.parameters_json;
  const json p = json::parse(text.empty() ? "{}" : text, nullptr, false);
  if (model.registration.kind == "face_images") {
    face_registration(out, model, p);
    return out;
  }
  const json reg = p.is_object() && p.contains("registration") ? p["registration"] : json::object();
  scale_and_orientation(out, reg, p);
  precision(out, p);
  matching(out, p);
  residual(out, model, reg);
  if (p.is_object() && p.contains("warnings") && p["warnings"].is_array())
    for (const auto& w : p["warnings"])
      if (w.is_string()) out.push_back({"Warning", w.get<std::string>(), true});
  if (out.empty()) out.push_back({"Registration", f::in_words(model.registration.kind)});
  return out;
}

}  // namespace rockface::ui
