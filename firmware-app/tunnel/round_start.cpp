#include "firmware-app/tunnel/round_start.h"

#include <algorithm>
#include <tuple>

#include "storage/tunnel/visit_heading.h"

namespace rockface::app {

std::string DriveFaces::heading_of(storage::RecordId visit_id) const {
  const auto it = headings.find(visit_id);
  return it == headings.end() ? std::string() : it->second;
}

double DriveFaces::sense_of(const std::string& heading) const {
  const double tunnel_sense = tunnel_drive == tunnel::Drive::ascending ? 1.0 : -1.0;
  if (heading.empty()) return tunnel_sense;
  std::vector<const PlacedFace*> own;
  for (const auto& f : faces)
    if (f.heading == heading) own.push_back(&f);
  if (own.size() < 2) return tunnel_sense;
  // By date, then by id (visits of one day stored in the order taken).
  std::sort(own.begin(), own.end(), [](const PlacedFace* a, const PlacedFace* b) {
    return std::tie(a->started_at, a->visit_id) < std::tie(b->started_at, b->visit_id);
  });
  // The trend's sign: the covariance of chainage with the visits' rank, so
  // that one face revisited out of turn does not turn the heading round.
  double mean_chainage = 0;
  for (const auto* f : own) mean_chainage += f->chainage;
  mean_chainage /= static_cast<double>(own.size());
  const double mean_rank = (static_cast<double>(own.size()) - 1) / 2;
  double covariance = 0;
  for (std::size_t i = 0; i < own.size(); ++i)
    covariance += (static_cast<double>(i) - mean_rank) * (own[i]->chainage - mean_chainage);
  if (covariance > 0) return 1.0;
  if (covariance < 0) return -1.0;
  return tunnel_sense;
}

std::optional<PlacedFace> DriveFaces::previous_face(storage::RecordId visit_id, double round_to,
                                                    double sense) const {
  const std::string heading = heading_of(visit_id);
  std::optional<PlacedFace> previous;
  for (const auto& f : faces)
    if (f.visit_id != visit_id && f.heading == heading && sense * f.chainage < sense * round_to &&
        (!previous || sense * f.chainage > sense * previous->chainage))
      previous = f;
  return previous;
}

DriveFaces drive_faces(storage::ProjectStore& store, tunnel::Drive tunnel_drive) {
  DriveFaces out;
  out.tunnel_drive = tunnel_drive;
  out.headings = storage::list_visit_headings(store);
  std::map<storage::RecordId, std::string> started;
  for (const auto& v : store.list_visits()) started[v.id] = v.started_at;
  for (const auto& p : store.list_visit_placements())
    out.faces.push_back({p.visit_id, p.chainage, out.heading_of(p.visit_id), started[p.visit_id]});
  return out;
}

}  // namespace rockface::app
