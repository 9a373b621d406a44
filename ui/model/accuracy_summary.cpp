#include "ui/model/accuracy_summary.h"

#include "storage/project/model_registration.h"
#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

namespace f = format;
using storage::ModelRegistration;

void scale_and_orientation(std::vector<AccuracyLine>& out, const ModelRegistration& reg) {
  if (!reg.imported_from.empty()) out.push_back({"3D image", "imported from " + reg.imported_from});
  const std::string& scale = reg.scale_source;
  if (scale == "range pole") {
    std::string v = "range pole";
    if (reg.pole_length_m && *reg.pole_length_m > 0)
      v += ", " + f::text(f::Length{*reg.pole_length_m}) + " between its targets";
    out.push_back({"Scale", v});
  } else if (!scale.empty()) {
    out.push_back({"Scale", f::in_words(scale)});
  } else if (reg.scaled == false) {
    out.push_back({"Scale", "not scaled: lengths are in units of the camera base", true});
  }
  if (!reg.vertical_source.empty()) out.push_back({"Vertical", f::in_words(reg.vertical_source)});
  if (reg.has_north) {
    std::string v = f::in_words(reg.north_source);
    if (reg.compass_azimuth_deg) v += ", line at " + f::azimuth(*reg.compass_azimuth_deg);
    if (reg.declination_deg && *reg.declination_deg != 0)
      v += ", declination " + f::text(f::Angle{*reg.declination_deg});
    out.push_back({"North", v});
  } else if (reg.north_source == "none") {
    out.push_back({"North", "not oriented: no compass line was given for this pair", true});
  } else if (!reg.north_source.empty()) {
    out.push_back({"North", f::in_words(reg.north_source)});
  } else if (reg.has_format) {
    out.push_back({"North", "not oriented to north", true});
  }
}

void precision(std::vector<AccuracyLine>& out, const ModelRegistration& reg) {
  if (const auto s = reg.predicted_depth_sigma_mm)
    out.push_back(
        {"Point precision", f::plus_minus(f::Length{*s / 1000}) + " in depth (1σ, predicted)"});
  if (const auto d = reg.distance_m) {
    std::string v = f::text(f::Length{*d});
    if (const auto b = reg.base_m) {
      v += ", base " + f::text(f::Length{*b});
      if (const auto r = reg.base_to_distance) v += " (" + f::one_in(*r) + ")";
    }
    out.push_back({"Distance to the face", v});
  }
  if (const auto s = reg.point_spacing_m) out.push_back({"Point spacing", f::text(f::Length{*s})});
}

void matching(std::vector<AccuracyLine>& out, const ModelRegistration& reg) {
  std::string v;
  if (reg.inliers && reg.matches)
    v = f::count(static_cast<std::int64_t>(*reg.inliers)) + " of " +
        f::count(static_cast<std::int64_t>(*reg.matches), "match", "matches") + " kept";
  if (const auto rms = reg.rms_reprojection_px)
    v += (v.empty() ? "" : ", ") + f::pixels(*rms) + " reprojection (rms)";
  if (const auto c = reg.tie_point_coverage)
    v += (v.empty() ? "" : ", ") + f::text(f::Fraction{*c}) + " of the image covered";
  if (!v.empty()) out.push_back({"Pair orientation", v});
  if (const auto valid = reg.dense_valid_fraction) {
    std::string m = f::text(f::Fraction{*valid}) + " of the pixels matched";
    if (const auto s = reg.dense_image_scale; s && *s < 0.999)
      m += ", at " + f::text(f::Fraction{*s}) + " of full resolution";
    out.push_back({"Surface matching", m});
  }
}

void residual(std::vector<AccuracyLine>& out, const storage::Model& model,
              const ModelRegistration& reg) {
  // A residual needs redundancy: two pole targets fix the scale and the
  // vertical exactly and leave nothing over to check them against.
  if (reg.has_control_points && model.residuals.size() >= 3) {
    std::string v = f::text(f::Length{model.registration.rms_m}) + " rms over " +
                    f::count(static_cast<std::int64_t>(model.residuals.size()), "control point",
                             "control points");
    if (reg.worst_control_m && !reg.worst_control.empty())
      v += ", worst " + reg.worst_control + " " + f::text(f::Length{*reg.worst_control_m});
    out.push_back({"Residual", v});
  } else {
    const bool pole = reg.has_pole;
    const std::int64_t n = pole ? 2 : static_cast<std::int64_t>(model.residuals.size());
    out.push_back({"Residual", "needs three or more targets (" +
                                   (n == 0 ? std::string("none here")
                                           : f::count(n, "target", "targets") + " here") +
                                   ": nothing over to check the scale against)"});
  }
}

void face_registration(std::vector<AccuracyLine>& out, const storage::Model& model,
                       const ModelRegistration& reg) {
  out.push_back({"Placed", "onto pair 1's 3D image (one face frame)"});
  for (const auto& i : reg.images) {
    if (i.role != "registered") continue;
    std::string v;
    if (i.tie_points)
      v = f::count(static_cast<std::int64_t>(*i.tie_points), "tie point", "tie points");
    if (i.tie_point_rms_m)
      v += (v.empty() ? "" : ", ") + f::text(f::Length{*i.tie_point_rms_m}) + " rms";
    if (i.overlap) v += (v.empty() ? "" : ", ") + f::text(f::Fraction{*i.overlap}) + " overlap";
    if (!v.empty()) out.push_back({"Tie points (" + f::file_name(i.name) + ")", v});
  }
  out.push_back({"Surface fit",
                 f::text(f::Length{model.registration.rms_m}) + " rms against pair 1's surface"});
  if (const auto s = reg.predicted_depth_sigma_mm)
    out.push_back(
        {"Point precision", f::plus_minus(f::Length{*s / 1000}) + " in depth (1σ, predicted)"});
}

}  // namespace

std::vector<AccuracyLine> accuracy_lines(const storage::Model& model) {
  std::vector<AccuracyLine> out;
  const ModelRegistration reg = storage::read_model_registration(model.registration);
  if (model.registration.kind == "face_images") {
    face_registration(out, model, reg);
    return out;
  }
  scale_and_orientation(out, reg);
  precision(out, reg);
  matching(out, reg);
  residual(out, model, reg);
  for (const auto& w : reg.warnings) out.push_back({"Warning", w, true});
  if (out.empty()) out.push_back({"Registration", f::in_words(reg.kind)});
  return out;
}

}  // namespace rockface::ui
