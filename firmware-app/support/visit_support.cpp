#include "firmware-app/support/visit_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/analysis/support_changes.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/orientation.h"
#include "firmware-app/records/project_visit.h"
#include "firmware-app/rockmass/visit_rock_mass.h"
#include "firmware-app/support/support_change_text.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/support/support_classes_json.h"

namespace rockface::app {

namespace {

constexpr double kRadPerDegree = std::numbers::pi / 180.0;
// Vertices of a block within this distance (along the drive) of its
// front-most one lie on the face: the exposed face's outline.
constexpr double kOnFaceM = 0.01;

kinematics::ModeType mode_type(const std::string& s) {
  if (s == "falling") return kinematics::ModeType::Falling;
  if (s == "lifting") return kinematics::ModeType::Lifting;
  if (s == "sliding") return kinematics::ModeType::Sliding;
  return kinematics::ModeType::None;
}

// The perimeter of the convex hull of 2D points (Andrew's monotone chain).
double hull_perimeter(std::vector<Eigen::Vector2d> p) {
  if (p.size() < 3) return 0;
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  double len = 0;
  for (std::size_t i = 0; i < h.size(); ++i) len += (h[(i + 1) % h.size()] - h[i]).norm();
  return len;
}

// The face's blocks that move, from the visit's latest analysis: the mode
// and resultant as stored, the sliding planes from the visit's joints, the
// exposed face from the block's free faces, the face bolts along the drive.
std::vector<analysis::MovingBlock> moving_blocks(storage::ProjectStore& store,
                                                 storage::RecordId visit,
                                                 const std::optional<Eigen::Vector3d>& drive,
                                                 std::vector<std::string>& notes) {
  std::vector<analysis::MovingBlock> out;
  const auto runs = store.list_analyses(visit);
  if (runs.empty()) return out;
  const auto latest = std::max_element(runs.begin(), runs.end(),
                                       [](const auto& a, const auto& b) { return a.id < b.id; });
  std::map<std::string, storage::Joint> joints;
  for (const auto& j : store.list_joints(visit)) joints[j.label] = j;
  int skipped = 0;
  for (const auto& b : store.load_analysis(latest->id).blocks) {
    if (!b.removable || !b.mode || b.mode->type == "none" || !b.mode->direction ||
        !b.resultant_force)
      continue;
    if (!drive) {
      ++skipped;
      continue;
    }
    analysis::MovingBlock m;
    m.id = b.id;
    m.mode.type = mode_type(b.mode->type);
    m.mode.direction = b.mode->direction->normalized();
    m.loads = *b.resultant_force;
    m.fos = b.fos;
    m.bolt_direction = *drive;
    bool known = true;
    for (std::size_t i = 0; i < b.mode->planes.size(); ++i) {
      const auto j = joints.find(b.mode->planes[i]);
      if (j == joints.end()) {
        known = false;
        break;
      }
      kinematics::ContactPlane c;
      c.plane = static_cast<int>(i);
      c.block_normal = geometry::plane_normal_deg(j->second.dip_deg, j->second.dipdir_deg);
      if (m.loads.dot(c.block_normal) > 0) c.block_normal = -c.block_normal;  // the side it presses
      if (j->second.friction_deg) c.friction = *j->second.friction_deg * kRadPerDegree;
      const auto area = b.face_areas.find(j->first);
      if (j->second.cohesion_pa && area != b.face_areas.end())
        c.cohesion_force = *j->second.cohesion_pa * area->second;
      m.mode.planes.push_back(c.plane);
      m.contacts.push_back(c);
    }
    if (!known) {
      notes.push_back("block " + b.id +
                      ": a sliding plane is not among the visit's joints; not checked");
      continue;
    }
    for (const auto& [id, area] : b.face_areas)
      if (!joints.count(id)) m.exposed_area_m2 += area;
    double lo = 1e300, hi = -1e300;
    for (const auto& v : b.vertices) {
      lo = std::min(lo, v.dot(*drive));
      hi = std::max(hi, v.dot(*drive));
    }
    m.depth_m = b.vertices.empty() ? 0 : hi - lo;
    // The exposed face's outline: the vertices on the face, in the face's plane.
    const Eigen::Vector3d e1 = drive->unitOrthogonal(), e2 = drive->cross(e1);
    std::vector<Eigen::Vector2d> front;
    for (const auto& v : b.vertices)
      if (v.dot(*drive) - lo < kOnFaceM) front.push_back({v.dot(e1), v.dot(e2)});
    m.exposed_outline_m = hull_perimeter(front);
    out.push_back(std::move(m));
  }
  if (skipped > 0)
    notes.push_back(std::to_string(skipped) +
                    " moving blocks of the face not checked: the visit is not placed in a tunnel "
                    "(no drive for the face bolts)");
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

void fill(storage::ProjectStore& store, storage::RecordId visit,
          const std::optional<std::string>& esr_use, VisitSupport& out,
          std::vector<analysis::MovingBlock>& blocks) {
  out.visit = visit;
  // The rock mass: RMR89 (the tunnel's, adjusted) and Q with their open lines.
  std::optional<rockmass::RockMassFigures> rm;
  try {
    rm = visit_rock_mass(store, visit);
  } catch (const InputError& e) {
    out.notes.push_back(std::string("no rock mass figures: ") + e.what());
  }
  if (rm) {
    out.figures.rmr = rm->rmr.adjusted.value;
    out.figures.rmr_missing = rm->rmr.adjusted.missing;
    out.figures.q = rm->q.q;
    out.figures.q_missing = rm->q.missing;
    out.span_m = rm->form.span_m;
    if (rm->form.esr) {
      out.esr = rm->form.esr;
      out.esr_source = "entered on the form";
    }
  } else {
    out.figures.rmr_missing = {"the rock mass figures"};
    out.figures.q_missing = {"the rock mass figures"};
  }
  if (esr_use) {
    const auto e = rockmass::esr_for(*esr_use);
    if (!e) {
      std::string keys;
      for (const auto& row : rockmass::esr_table())
        keys += (keys.empty() ? "" : ", ") + std::string(row.key);
      throw InputError("--esr",
                       "\"" + *esr_use + "\" is not an excavation of the ESR table (" + keys + ")");
    }
    out.esr = e->esr;
    out.esr_source = std::string("NGI 2015 table: ") + e->words;
  }

  // The Q chart and Bieniawski's table.
  if (!out.figures.q)
    out.q_support_why = "Q is open (" + join(out.figures.q_missing) + " not entered)";
  else if (!out.span_m)
    out.q_support_why = "the span is not known (no tunnel profile, none entered)";
  else if (!out.esr)
    out.q_support_why = "ESR not entered (the form's ESR, or --esr with the excavation's use)";
  else {
    out.q_point = rockmass::QChartPoint{*out.figures.q, *out.span_m, *out.esr};
    out.q_support = rockmass::q_support(*out.q_point);
  }
  if (out.figures.rmr)
    out.rmr_support = rockmass::rmr_support_guidelines(*out.figures.rmr, out.span_m);
  else
    out.rmr_support_why = "RMR89 is open (" + join(out.figures.rmr_missing) + " not entered)";

  // The wedges without support (their sizes and behaviour) and the face's blocks.
  std::string why;
  const auto wedges = project_visit_wedges(store, visit, &why);
  bool structural = false;
  if (wedges) {
    out.figures.wedges_known = true;
    for (const auto& w : wedges->analysis.wedges) {
      if (!w.removable.value) continue;
      if (!out.figures.largest_wedge_volume_m3 ||
          w.mass.volume > *out.figures.largest_wedge_volume_m3) {
        out.figures.largest_wedge_volume_m3 = w.mass.volume;
        out.figures.largest_wedge_apex_m = w.apex_height;
      }
      if (w.mode && w.mode->type != kinematics::ModeType::None && w.fos && *w.fos < 1)
        structural = true;
    }
    if (!wedges->run.options.bolts) {
      for (const auto& note : wedges->run.notes)
        if (note.find("friction") != std::string::npos) out.notes.push_back("wedges: " + note);
    }
  } else {
    out.notes.push_back("no wedges: " + why);
  }
  std::optional<Eigen::Vector3d> drive;
  const auto tunnel = store.load_tunnel();
  const auto placement = store.load_visit_placement(visit);
  if (tunnel && placement) {
    out.chainage = placement->chainage;
    drive = tunnel->alignment(store.project().datum).tangent_at(placement->chainage);
  }
  blocks = moving_blocks(store, visit, drive, out.notes);
  for (const auto& b : blocks)
    if (b.fos && *b.fos < 1) structural = true;
  if (wedges || !blocks.empty())
    out.figures.behaviour =
        structural ? analysis::kBehaviourStructural : analysis::kBehaviourStable;
}

analysis::SupportCheck check_class(storage::ProjectStore& store, storage::RecordId visit,
                                   const analysis::SupportClass& c,
                                   const std::vector<analysis::MovingBlock>& blocks) {
  std::optional<tunnel::WedgeAnalysis> supported, face_supported;
  std::optional<WedgeRun> run;
  try {
    run = wedge_run_from_project(store, visit, {});
    WedgeRun pattern = *run;
    pattern.options = analysis::with_class_support(run->options, c);
    supported = run_wedges(pattern);
  } catch (const InputError&) {
    // No tunnel or fewer than three sets: said by check_support.
  }
  std::string face_refused;
  if (supported && analysis::has_face_support(c)) {
    // The face wedges again, under the class's face support.
    try {
      WedgeRun face = *run;
      face.options = analysis::with_class_face_support(run->options, c);
      face_supported = run_wedges(face);
    } catch (const InputError& e) {
      face_refused = e.what();  // a face support outside the ranges a wedge analysis takes
    }
  }
  analysis::SupportCheck out = analysis::check_support(c, supported ? &*supported : nullptr, blocks,
                                                       face_supported ? &*face_supported : nullptr);
  if (!face_refused.empty())
    out.notes.push_back("face support on the face wedges: " + face_refused);
  return out;
}

void add_checks(storage::ProjectStore& store, VisitSupport& out,
                const std::vector<analysis::MovingBlock>& blocks) {
  if (!out.classes) return;
  std::vector<std::string> names;
  if (out.proposal && out.proposal->proposed) names.push_back(*out.proposal->proposed);
  if (out.decision &&
      std::find(names.begin(), names.end(), out.decision->class_name) == names.end())
    names.push_back(out.decision->class_name);
  for (const auto& n : names)
    if (const analysis::SupportClass* c = analysis::find_class(*out.classes, n))
      out.checks.push_back(check_class(store, out.visit, *c, blocks));
}

// The chosen class with the decision's changes, checked. A decision being
// made (`deciding`) has its changes refused by name (InputError naming
// --change); a stored one whose changes no longer apply (made before they
// were checked, or the classes replaced since) is said in the notes.
void add_decided_check(storage::ProjectStore& store, VisitSupport& out,
                       const std::vector<analysis::MovingBlock>& blocks, bool deciding) {
  if (!out.classes || !out.decision || out.decision->changes.empty()) return;
  const analysis::SupportClass* c = analysis::find_class(*out.classes, out.decision->class_name);
  if (!c) return;
  std::optional<analysis::ChangedPattern> changed;
  try {
    changed = analysis::apply_support_changes(*c, out.decision->changes, "--change");
  } catch (const InputError& e) {
    if (deciding) throw;
    out.notes.push_back("the decision's changes are not applied to its check (" + e.reason() +
                        "): the check shown is the class's");
    return;
  }
  changed->pattern.name = c->name + " as changed";
  out.decided_check = check_class(store, out.visit, changed->pattern, blocks);
  for (const auto& n : changed->notes) out.decided_check->notes.push_back(n);
}

}  // namespace

std::string checks_words(const analysis::SupportCheck& c) {
  int wedges_below = 0, blocks_below = 0;
  std::string which;
  for (const auto& w : c.wedges)
    if (w.below_target) {
      ++wedges_below;
      which += (which.empty() ? "" : ", ") + w.id + " " + w.place;
    }
  for (const auto& b : c.blocks)
    if (b.below_target) {
      ++blocks_below;
      which += (which.empty() ? "" : ", ") + std::string("block ") + b.id;
    }
  return c.class_name + ": " + std::to_string(wedges_below) + " of " +
         std::to_string(c.wedges.size()) + " wedges and " + std::to_string(blocks_below) + " of " +
         std::to_string(c.blocks.size()) + " moving blocks below FoS " +
         format_significant(c.target_fos, 3) + (which.empty() ? "" : " (" + which + ")");
}

std::string decision_checks_words(const VisitSupport& s) {
  if (!s.decision) return "";
  const analysis::SupportCheck* unchanged = nullptr;
  for (const auto& c : s.checks)
    if (c.class_name == s.decision->class_name) unchanged = &c;
  if (!s.decided_check) return unchanged ? checks_words(*unchanged) : "";
  return checks_words(*s.decided_check) +
         (unchanged ? "; the class unchanged: " + checks_words(*unchanged) : "");
}

VisitSupport visit_support(storage::ProjectStore& store, storage::RecordId visit,
                           const std::optional<std::string>& esr_use) {
  require_visit(store, visit);
  VisitSupport out;
  std::vector<analysis::MovingBlock> blocks;
  fill(store, visit, esr_use, out, blocks);
  out.classes = store.load_support_classes();
  if (out.classes) out.proposal = analysis::match_support_classes(*out.classes, out.figures);
  out.decision = store.load_support_decision(visit);
  add_checks(store, out, blocks);
  add_decided_check(store, out, blocks, false);
  return out;
}

VisitSupport visit_support(const SupportRequest& q) {
  if (q.decide && !q.by) throw InputError("--by", "a decision names who decided (--by NAME)");
  if (!q.decide && (q.by || q.reason))
    throw InputError(q.by ? "--by" : "--reason", "goes with --decide CLASS");
  if (!q.decide && !q.changes.empty()) throw InputError("--change", "goes with --decide CLASS");
  for (const auto& c : q.changes) require_complete(c, "--change");
  // Read the classes before opening the project for writing: a refused
  // file leaves the project as it was.
  std::optional<analysis::SupportClasses> file_classes;
  if (q.classes_file) file_classes = storage::load_support_classes(*q.classes_file);
  storage::OpenOptions options;
  options.read_only = !q.classes_file && !q.decide;
  storage::ProjectStore store = storage::ProjectStore::open(q.project, options);
  require_visit(store, q.visit);
  if (file_classes) store.save_support_classes(*file_classes);

  VisitSupport out;
  std::vector<analysis::MovingBlock> blocks;
  fill(store, q.visit, q.esr_use, out, blocks);
  out.classes = store.load_support_classes();
  if (out.classes) out.proposal = analysis::match_support_classes(*out.classes, out.figures);
  out.decision = store.load_support_decision(q.visit);
  if (q.decide) {
    if (!out.classes)
      throw InputError("--decide", "the project has no support classes (--classes FILE)");
    if (!analysis::find_class(*out.classes, *q.decide)) {
      std::string names;
      for (const auto& c : out.classes->classes) names += (names.empty() ? "" : ", ") + c.name;
      throw InputError("--decide",
                       "\"" + *q.decide + "\" is not a class of the tunnel (" + names + ")");
    }
    const std::string proposed =
        out.proposal && out.proposal->proposed ? *out.proposal->proposed : "";
    if (*q.decide != proposed && (!q.reason || q.reason->empty()))
      throw InputError("--reason", "class " + *q.decide + " is not the proposed " +
                                       (proposed.empty() ? std::string("(none)") : proposed) +
                                       ": say why (--reason TEXT)");
    analysis::SupportDecision d;
    d.class_name = *q.decide;
    d.proposed = proposed;
    d.reason = q.reason.value_or("");
    d.changes = q.changes;
    d.decided_by = *q.by;
    d.decided_at = storage::utc_now_iso8601();
    out.decision = d;
    // The changes refused before anything is checked or stored.
    analysis::apply_support_changes(*analysis::find_class(*out.classes, d.class_name), d.changes,
                                    "--change");
    add_checks(store, out, blocks);
    add_decided_check(store, out, blocks, true);
    out.decision->checks = decision_checks_words(out);
    store.save_support_decision(q.visit, *out.decision);
    return out;
  }
  add_checks(store, out, blocks);
  add_decided_check(store, out, blocks, false);
  return out;
}

}  // namespace rockface::app
