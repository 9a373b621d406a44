#include "storage/scene/export_scene_json.h"

#include <map>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

namespace {

nlohmann::json point(const Eigen::Vector3d& datum, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = datum + p;
  return nlohmann::json::array({a.x(), a.y(), a.z()});
}

nlohmann::json points(const Eigen::Vector3d& datum, const std::vector<Eigen::Vector3d>& ps) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : ps) out.push_back(point(datum, p));
  return out;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& ps) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : ps) sum += p;
  return sum / static_cast<double>(ps.size());
}

}  // namespace

std::vector<photogrammetry::FaceTrace> scene_traces(const std::vector<Measurement>& measurements) {
  // One image per model; a trace stored without a model is an image of its
  // own kind (-1): such traces were measured on one 3D image.
  std::map<RecordId, int> image_of_model;
  std::vector<photogrammetry::TracePiece> pieces;
  for (const auto& m : measurements) {
    if (m.kind != Measurement::Kind::trace) continue;
    int image = -1;
    if (m.model_id)
      image = image_of_model.emplace(*m.model_id, static_cast<int>(image_of_model.size()))
                  .first->second;
    pieces.push_back({m.label, m.joint_label, image, m.points});
  }
  return photogrammetry::join_trace_pieces(pieces);
}

nlohmann::json make_scene_json(const SceneSource& source) {
  const Eigen::Vector3d& datum = source.project.datum;
  nlohmann::json scene;
  scene["format"] = "rockface-scene/1";
  scene["name"] = source.project.name;
  scene["datum"] = nlohmann::json::array({datum.x(), datum.y(), datum.z()});
  scene["source"] = {{"project", source.project.name}, {"visit", source.visit_id}};

  nlohmann::json joints = nlohmann::json::array();
  for (const auto& j : source.joints) {
    nlohmann::json e = {{"id", j.label}, {"dip", j.dip_deg}, {"dipdir", j.dipdir_deg}};
    if (j.point) e["point"] = point(datum, *j.point);
    if (j.friction_deg) e["friction"] = *j.friction_deg;
    if (j.cohesion_pa) e["cohesion"] = *j.cohesion_pa;
    if (!j.set_label.empty()) e["set"] = j.set_label;
    joints.push_back(std::move(e));
  }
  scene["joints"] = std::move(joints);

  nlohmann::json free_faces = nlohmann::json::array();
  nlohmann::json patches = nlohmann::json::array();
  nlohmann::json traces = nlohmann::json::array();
  for (const auto& m : source.measurements) {
    if (m.kind == Measurement::Kind::area) {
      patches.push_back({{"id", m.label}, {"polygon", points(datum, m.points)}});
      // A free face needs its plane and the side the rock is on; an area
      // without them is surface only.
      if (m.dip_deg && !m.rock_side.empty())
        free_faces.push_back({{"id", m.label},
                              {"dip", *m.dip_deg},
                              {"dipdir", *m.dipdir_deg},
                              {"point", point(datum, centroid(m.points))},
                              {"rock_side", m.rock_side}});
    }
  }
  for (const auto& ft : scene_traces(source.measurements)) {
    nlohmann::json t = {{"id", ft.label}, {"points", points(datum, ft.points)}};
    if (!ft.joint.empty()) t["joint"] = ft.joint;
    // Issue 27: a trace assigned to no joint that has a joint of its own
    // (made of it alone, its plane fitted or read with a compass) lies in
    // that joint: without it a straight trace, whose plane only the compass
    // gives, would have no plane in the trace map.
    for (const auto& j : source.joints)
      if (ft.joint.empty() && j.type == "trace" && j.label == ft.label &&
          (j.source == "trace " + j.label || j.source == "trace " + j.label + " (compass)"))
        t["joint"] = j.label;
    if (ft.pieces.size() > 1) t["pieces"] = ft.pieces;
    traces.push_back(std::move(t));
  }
  scene["free_faces"] = std::move(free_faces);
  scene["surface"] = {{"patches", std::move(patches)}};
  scene["traces"] = std::move(traces);

  nlohmann::json analysis = {{"pyramids", true}, {"blocks", true}};
  if (source.analysis) {
    if (!source.analysis->preset.empty()) analysis["preset"] = source.analysis->preset;
    if (!source.analysis->effects_json.empty()) {
      auto effects = nlohmann::json::parse(source.analysis->effects_json, nullptr, false);
      if (!effects.is_discarded() && effects.is_object()) scene["effects"] = std::move(effects);
    }
  }
  scene["analysis"] = std::move(analysis);
  return scene;
}

SceneSource load_scene_source(ProjectStore& store, std::optional<RecordId> visit_id) {
  SceneSource source;
  source.project = store.project();
  if (!visit_id) visit_id = store.latest_visit();
  if (!visit_id) throw InputError(store.file().string(), "the project has no visit");
  source.visit_id = *visit_id;
  source.joints = store.list_joints(visit_id);
  source.measurements = store.list_measurements(visit_id);
  const auto analyses = store.list_analyses(visit_id);
  if (!analyses.empty()) source.analysis = analyses.back();
  return source;
}

void export_scene_json(ProjectStore& store, const std::filesystem::path& file,
                       std::optional<RecordId> visit_id) {
  const SceneSource source = load_scene_source(store, visit_id);
  const nlohmann::json scene = make_scene_json(source);
  write_file_atomically(file, [&](std::ostream& out) { out << scene.dump(2) << '\n'; });
  if (!store.read_only()) store.log_action(source.visit_id, "export scene json", file.string());
}

}  // namespace rockface::storage
