#include "ui/blocks/block_view.h"

#include <nlohmann/json.hpp>

#include "storage/report/report_dynamics_json.h"
#include "ui/blocks/block_summary.h"

namespace rockface::ui {

BlockView make_block_view(const storage::BlockResult& block, const Eigen::Vector3d& datum) {
  BlockView v;
  v.label = block.label;
  v.source = block.source;
  v.code = block.code;
  v.mode = block.mode;
  v.finite = block.finite;
  v.removable = block.removable;
  v.marginal = block.marginal;
  v.fos = block.fos;
  const auto json = nlohmann::json::parse(block.report_json, nullptr, false);
  if (json.is_object()) {
    v.report_text = json.dump(2);
    if (json.contains("margin_deg") && json["margin_deg"].is_number())
      v.margin_deg = json["margin_deg"].get<double>();
    if (json.contains("vertices") && json["vertices"].is_array())
      for (const auto& p : json["vertices"])
        if (p.is_array() && p.size() == 3)
          v.vertices.push_back(
              Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()) - datum);
    // analyse_traces.cpp notes it so ("vertices: the loop on the free surface ...").
    if (json.contains("notes") && json["notes"].is_array())
      for (const auto& n : json["notes"])
        if (n.is_string() &&
            n.get<std::string>().rfind("vertices: the loop on the free surface", 0) == 0)
          v.vertices_are_surface_loop = true;
    if ((v.dynamics = storage::dynamics_from_block_json(block.report_json))) {
      for (auto& s : v.dynamics->path) s.position -= datum;
      if (v.dynamics->landing) {
        v.dynamics->landing->point -= datum;
        v.dynamics->landing->centroid -= datum;
      }
      if (v.dynamics->floor) v.dynamics->floor->first -= datum;
    }
    if (json.contains("rotation") && json["rotation"].is_object()) {
      bool any = false;
      for (const char* part : {"corners", "edges"})
        if (json["rotation"].contains(part))
          for (const auto& item : json["rotation"][part])
            any = any || item.value("rotatable", false);
      v.rotatable = any;
    }
  } else {
    v.report_text = block.report_json;
  }
  v.verdict = verdict_of(block);
  v.summary = block_summary(block, json.is_object() ? json : nlohmann::json::object());
  return v;
}

}  // namespace rockface::ui
