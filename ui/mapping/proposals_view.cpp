#include "ui/mapping/proposals_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <imgui_internal.h>
#include <opencv2/imgproc.hpp>

#include "core/common/units.h"
#include "core/measure/least_cost_trace.h"
#include "storage/project/model_registration.h"
#include "ui/app/screens.h"
#include "ui/widgets/format.h"
#include "ui/widgets/picture_texture.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// A finger's width around a proposal's line picks it (at scale 1).
constexpr float kPickRadiusPx = 24;
// The photograph in the side panel is drawn at most this wide (px).
constexpr int kPhotoWidthPx = 640;
// A corrected trace is measured on every this many pixels of its path.
constexpr std::size_t kCorrectionStepPx = 4;

// Low confidence orange, high green: the colour says how sure, the list
// says the number.
ImU32 confidence_colour(double c) {
  const double t = std::clamp((c - 0.15) / 0.85, 0.0, 1.0);
  return IM_COL32(static_cast<int>(255 * (1 - t)), static_cast<int>(140 + 80 * t),
                  static_cast<int>(120 * t), 255);
}

bool current(const AppState& app) {
  const ProposalsState& s = app.mapping.proposals;
  return s.result && s.model_id == app.model_view.model_id();
}

bool shown(const ProposalsState& s, const measure::TraceProposal& p) {
  return !s.rejected.count(p.id) && !s.accepted.count(p.id) && !s.mapped.count(p.id);
}

// A proposal lies along a stored trace when most of its points are within
// the proposals' own facet tolerance (5 cm: a trace's width on the rock and
// the tap's spread) of that trace's polyline.
bool along_stored_trace(const measure::TraceProposal& p,
                        const std::vector<storage::Measurement>& traces) {
  constexpr double kNear = 0.05, kShare = 0.6;
  if (p.trace.points.empty()) return false;
  for (const auto& t : traces) {
    if (t.points.size() < 2) continue;
    std::size_t near = 0;
    for (const Eigen::Vector3d& q : p.trace.points) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < t.points.size(); ++i) {
        const Eigen::Vector3d a = t.points[i - 1], d = t.points[i] - a;
        const double along =
            d.squaredNorm() > 0 ? std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        best = std::min(best, (a + along * d - q).norm());
      }
      near += best <= kNear;
    }
    if (static_cast<double>(near) >= kShare * static_cast<double>(p.trace.points.size()))
      return true;
  }
  return false;
}

void mark_mapped(AppState& app) {
  ProposalsState& s = app.mapping.proposals;
  s.mapped.clear();
  if (!s.result || !app.session) return;
  std::vector<storage::Measurement> traces;
  for (const auto& m : app.session->measurements())
    if (m.kind == storage::Measurement::Kind::trace && m.model_id == s.model_id)
      traces.push_back(m);
  for (const auto& p : s.result->proposals)
    if (along_stored_trace(p, traces)) s.mapped.insert(p.id);
}

// The model's depth precision, as for a hand trace (mapping_screen.cpp).
double point_sigma(const AppState& app) {
  if (const auto* m = app.model_view.model())
    if (const auto s = storage::read_model_registration(m->registration).predicted_depth_sigma_mm)
      return *s / 1000;
  return measure::MeasureSettings{}.point_sigma;
}

// The name of an arriving proposal until the whole result names it.
std::string arrival_name(std::size_t index) {
  return "found " + std::to_string(index + 1);
}

// The batches the worker has measured since the last frame, added to the
// provisional result (in the order they came: the list does not reorder
// under a finger).
void take_arriving(AppState& app) {
  ProposalsState& s = app.mapping.proposals;
  if (!s.arriving) return;
  std::vector<measure::TraceProposal> fresh;
  {
    std::lock_guard<std::mutex> lock(s.arriving->mutex);
    const auto& all = s.arriving->proposals;
    if (all.size() == s.arrived) return;
    fresh.assign(all.begin() + static_cast<std::ptrdiff_t>(s.arrived), all.end());
    s.arrived = all.size();
  }
  auto result = std::make_shared<measure::ProposalResult>();
  if (s.provisional && s.result) {
    result->proposals = s.result->proposals;
  } else {
    // The first batch: whatever was shown before (another model, or an
    // earlier search on this one) gives way, the search's hand-over kept.
    ProposalsState next;
    next.arriving = std::move(s.arriving);
    next.arriving_model = s.arriving_model;
    next.arrived = s.arrived;
    next.photo = std::move(s.photo);
    if (s.model_id == s.arriving_model) next.rejected = std::move(s.rejected);
    s = std::move(next);
    s.model_id = s.arriving_model;
  }
  for (auto& p : fresh) {
    p.id = arrival_name(result->proposals.size());
    p.trace.id = p.id;
    result->proposals.push_back(std::move(p));
  }
  s.result = std::move(result);
  s.provisional = true;
  s.photo_stale = true;
  mark_mapped(app);
}

// The whole result in place of the arriving proposals: what the geologist
// rejected or selected among them carries over to the same proposal (the
// same points) under its final name.
void carry_over_arrivals(ProposalsState& s, const measure::ProposalResult& whole) {
  if (!s.provisional || !s.result) return;
  const auto& early = s.result->proposals;
  const std::optional<std::size_t> selected = s.selected;
  s.selected.reset();
  for (std::size_t i = 0; i < whole.proposals.size(); ++i)
    for (std::size_t k = 0; k < early.size(); ++k) {
      if (early[k].trace.points != whole.proposals[i].trace.points) continue;
      if (s.rejected.erase(early[k].id)) s.rejected.insert(whole.proposals[i].id);
      if (selected == k) s.selected = i;
    }
}

void find_traces(AppState& app) {
  ProposalInput input;
  input.mesh = app.model_view.surface();
  input.picker = app.model_view.picker();
  auto view = std::make_shared<measure::PhotoView>(*app.model_view.left_view());
  input.photo = app.model_view.photo();
  input.point_sigma_m = point_sigma(app);
  try {
    input.preset = parse_preset(app.model_view.model()->preset, "model preset");
  } catch (const InputError&) {
    input.preset = Preset::standard;  // a model of an older program without a preset
  }
  ProposalRunner* runner = app.services.proposals;
  auto result = std::make_shared<measure::ProposalResult>();
  const storage::RecordId model = app.model_view.model_id();
  auto arriving = std::make_shared<ArrivingProposals>();
  const bool started = app.task.start(
      "Finding traces",
      [runner, input, view, result, arriving](Progress& progress) mutable {
        input.view = view.get();
        *result = runner->propose(
            input, progress, [arriving](const std::vector<measure::TraceProposal>& batch) {
              std::lock_guard<std::mutex> lock(arriving->mutex);
              arriving->proposals.insert(arriving->proposals.end(), batch.begin(), batch.end());
            });
        return std::to_string(result->proposals.size()) + " traces proposed";
      },
      [&app, model, result, arriving](const TaskOutcome& outcome) {
        ProposalsState& s = app.mapping.proposals;
        if (s.arriving == arriving) s.arriving.reset();
        if (outcome.kind == TaskOutcome::Kind::failed) s.problem = outcome.message;
        if (outcome.kind != TaskOutcome::Kind::done) {
          // Cancelled or failed: the arriving proposals were never named
          // nor ranked; none is offered to store.
          if (s.provisional) {
            s.result.reset();
            s.provisional = false;
            s.selected.reset();
            s.photo_stale = true;
          }
          return;
        }
        if (s.model_id != model) s = ProposalsState{};  // another model: start afresh
        carry_over_arrivals(s, *result);
        if (!s.provisional) s.selected.reset();
        s.model_id = model;
        s.result = result;
        s.provisional = false;
        s.problem.clear();
        s.ends.reset();
        s.corrected.reset();
        s.photo_stale = true;
        mark_mapped(app);
      });
  if (!started) return;
  ProposalsState& s = app.mapping.proposals;
  s.arriving = arriving;
  s.arriving_model = model;
  s.arrived = 0;
}

// A trace record of a measurement made on the left photograph of the model
// on display, as save_trace makes for a tapped trace.
storage::Measurement trace_record(const AppState& app, const measure::TraceMeasurement& t,
                                  const std::string& origin) {
  storage::Measurement m;
  m.visit_id = *app.session->visit();
  m.model_id = app.model_view.model_id();
  m.kind = storage::Measurement::Kind::trace;
  m.joint_label = app.mapping.joint_label;
  m.points = t.points;
  const storage::Model* model = app.model_view.model();
  if (model && model->texture_capture_id && model->texture_side == "left") {
    m.photo = "left";
    m.photo_capture_id = model->texture_capture_id;
    for (const auto& p : t.picks) m.pixels.push_back(p.pixel);
  }
  if (t.plane.known) {
    m.dip_deg = rad_to_deg(t.plane.orientation.dip);
    m.dipdir_deg = rad_to_deg(t.plane.orientation.dipdir);
    m.sigma_deg = rad_to_deg(t.plane.sigma);
  }
  m.fit_rms_m = t.plane.fit.rms_off_plane();
  m.trace_length_m = t.length;
  m.censored = t.censored;
  m.note = t.plane.problem;
  m.origin = origin;
  return m;
}

// The least-cost path between the dragged ends through the photograph's
// dark line, measured like a hand trace.
void retrace(AppState& app) {
  ProposalsState& s = app.mapping.proposals;
  s.corrected.reset();
  s.correction_problem.clear();
  const auto& view = *app.model_view.left_view();
  const auto px = measure::project_to_view(view, {(*s.ends)[0], (*s.ends)[1]});
  try {
    measure::TraceRequest request;
    request.from = px[0];
    request.to = px[1];
    request.cost = measure::TraceCost::Darkness;
    const auto path = measure::trace_between(app.model_view.photo(), app.model_view.surface(),
                                             request, "the corrected trace");
    std::vector<Eigen::Vector2d> pixels;
    for (std::size_t i = 0; i < path.pixels.size(); i += kCorrectionStepPx)
      pixels.push_back(path.pixels[i]);
    if (pixels.back() != path.pixels.back()) pixels.push_back(path.pixels.back());
    measure::MeasureSettings settings;
    settings.point_sigma = point_sigma(app);
    s.corrected = measure::measure_trace(*app.model_view.picker(), view, "", pixels, settings,
                                         "the corrected trace");
  } catch (const InputError& e) {
    s.correction_problem = e.what();
  }
}

void draw_photo(AppState& app) {
  ProposalsState& s = app.mapping.proposals;
  const cv::Mat& photo = app.model_view.photo();
  if (photo.empty()) return;
  if (!s.photo) s.photo = std::make_shared<PictureTexture>();
  if (s.photo_stale) {
    const double k = std::min(1.0, static_cast<double>(kPhotoWidthPx) / photo.cols);
    cv::Mat small;
    cv::resize(photo, small, cv::Size(), k, k, cv::INTER_AREA);
    for (std::size_t i = 0; i < s.result->proposals.size(); ++i) {
      const auto& p = s.result->proposals[i];
      if (!shown(s, p)) continue;
      std::vector<cv::Point> line;
      for (const auto& pick : p.trace.picks)
        line.emplace_back(static_cast<int>(std::lround(pick.pixel.x() * k)),
                          static_cast<int>(std::lround(pick.pixel.y() * k)));
      const ImU32 c = confidence_colour(p.confidence);
      const bool selected = s.selected == i;
      cv::polylines(small, line, false,
                    selected ? cv::Scalar(255, 255, 255)
                             : cv::Scalar((c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF),
                    selected ? 3 : 2, cv::LINE_AA);
    }
    s.photo->set(small);
    s.photo_stale = false;
  }
  s.photo->draw(ImGui::GetContentRegionAvail().x);
}

void draw_selected(AppState& app, const measure::TraceProposal& p) {
  ProposalsState& s = app.mapping.proposals;
  const bool can_store = !app.task.running() && app.session->visit() && !app.session->read_only();
  paragraph(p.id + ": " + format::text(format::Fraction{p.confidence}) + " sure, " +
            measure::proposal_cue_name(p.cue) + ", " +
            format::text(format::Length{p.trace.length}));
  if (p.trace.plane.known)
    paragraph(format::dip_and_direction(rad_to_deg(p.trace.plane.orientation.dip),
                                        rad_to_deg(p.trace.plane.orientation.dipdir)) +
              " ± " + format::text(format::Angle{rad_to_deg(p.trace.plane.sigma)}));
  else
    paragraph(p.trace.plane.problem);
  if (p.cue != measure::ProposalCue::fold)
    paragraph("dark line " + format::count(std::lround(p.contrast_grey)) +
              " grey levels darker than its sides");
  if (p.fold_fraction > 0)
    paragraph(std::string(p.ridge ? "ridge" : "valley") + " of " +
              format::text(format::Angle{p.fold_deg}) + " along " +
              format::text(format::Fraction{p.fold_fraction}) + " of it");
  if (p.facet_id) paragraph("on the edge of facet F" + std::to_string(*p.facet_id));
  if (!s.ends) {
    if (app.targets.button("Accept", 0, can_store) &&
        store_trace(app, trace_record(app, p.trace, "proposed"))) {
      s.accepted.insert(p.id);
      s.selected.reset();
      s.photo_stale = true;
    }
    ImGui::SameLine();
    // A correction waits for the whole result, which would end it.
    if (app.targets.button("Correct", 0, !p.trace.points.empty() && !s.provisional)) {
      s.ends = std::array<Eigen::Vector3d, 2>{p.trace.points.front(), p.trace.points.back()};
      retrace(app);
    }
    ImGui::SameLine();
    if (app.targets.button("Reject")) {
      s.rejected.insert(p.id);
      s.selected.reset();
      s.photo_stale = true;
    }
    return;
  }
  paragraph(
      "Drag the two ends where the trace really ends: it is traced again along "
      "the dark line between them.");
  if (!s.correction_problem.empty()) paragraph(s.correction_problem);
  if (app.targets.button("Save correction", 0, can_store && s.corrected.has_value()) &&
      store_trace(app, trace_record(app, *s.corrected, "corrected"))) {
    s.accepted.insert(p.id);
    s.selected.reset();
    s.ends.reset();
    s.corrected.reset();
    s.photo_stale = true;
    return;
  }
  ImGui::SameLine();
  if (app.targets.button("Cancel correction")) {
    s.ends.reset();
    s.corrected.reset();
  }
}

}  // namespace

void draw_proposal_panel(AppState& app) {
  if (!app.services.proposals) return;
  take_arriving(app);
  ProposalsState& s = app.mapping.proposals;
  ImGui::Separator();
  const bool ready = app.model_view.left_view() && !app.model_view.photo().empty() &&
                     app.model_view.picker() && app.model_view.surface();
  if (app.targets.button("Find traces", 0, ready && !app.task.running())) find_traces(app);
  if (!ready) {
    ImGui::SameLine();
    label_in_row("needs the model's photograph and camera");
  }
  if (!s.problem.empty()) paragraph(s.problem);
  if (!current(app)) return;
  const auto& proposals = s.result->proposals;
  std::size_t left = 0;
  for (const auto& p : proposals) left += shown(s, p);
  if (s.provisional)
    paragraph(format::count(static_cast<std::int64_t>(left), "proposed trace", "proposed traces") +
              " so far, the longest first; the rest as they are found (they can be stored "
              "once all are found)");
  else
    paragraph(format::count(static_cast<std::int64_t>(left), "proposed trace", "proposed traces") +
              " to decide; " + format::count(static_cast<std::int64_t>(s.accepted.size())) +
              " accepted, " + format::count(static_cast<std::int64_t>(s.rejected.size())) +
              " rejected, " + format::count(static_cast<std::int64_t>(s.mapped.size())) +
              " already mapped");
  if (s.selected && *s.selected < proposals.size()) {
    draw_selected(app, proposals[*s.selected]);
  } else {
    paragraph(
        "Tap a proposed trace on the model (or its name) to accept, correct or "
        "reject it.");
  }
  for (std::size_t i = 0; i < proposals.size(); ++i) {
    const auto& p = proposals[i];
    if (!shown(s, p)) continue;
    if (app.targets.button(p.id)) {
      s.selected = i;
      s.ends.reset();
      s.photo_stale = true;
    }
    ImGui::SameLine();
    label_in_row(format::text(format::Fraction{p.confidence}) + "  " +
                     format::text(format::Length{p.trace.length}) + "  " +
                     measure::proposal_cue_name(p.cue),
                 confidence_colour(p.confidence));
  }
  draw_photo(app);
}

void draw_proposals_on_model(AppState& app) {
  take_arriving(app);
  if (!current(app)) return;
  ProposalsState& s = app.mapping.proposals;
  const float scale = app.targets.scale();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const auto& proposals = s.result->proposals;
  for (std::size_t i = 0; i < proposals.size(); ++i) {
    const auto& p = proposals[i];
    if (!shown(s, p)) continue;
    std::vector<ImVec2> line;
    for (const auto& x : p.trace.points)
      if (const auto q = app.model_view.to_screen(x)) line.push_back(*q);
    if (line.size() < 2) continue;
    const bool selected = s.selected == i;
    if (selected)
      draw->AddPolyline(line.data(), static_cast<int>(line.size()), IM_COL32(255, 255, 255, 255), 0,
                        8 * scale);
    draw->AddPolyline(line.data(), static_cast<int>(line.size()), confidence_colour(p.confidence),
                      0, (selected ? 5 : 3) * scale);
    const ImVec2 mid = line[line.size() / 2];
    // What a tap picks (tap_proposal): the line within half a target.
    const float r = app.targets.target_px() / 2;
    app.targets.record("proposal " + p.id, ImVec2(mid.x - r, mid.y - r),
                       ImVec2(mid.x + r, mid.y + r));
  }
  if (s.ends) {
    if (s.corrected) {
      std::vector<ImVec2> line;
      for (const auto& x : s.corrected->points)
        if (const auto q = app.model_view.to_screen(x)) line.push_back(*q);
      draw->AddPolyline(line.data(), static_cast<int>(line.size()), kPendingTraceColour, 0,
                        4 * scale);
    }
    for (const auto& e : *s.ends)
      if (const auto q = app.model_view.to_screen(e)) {
        draw->AddCircleFilled(*q, 12 * scale, kPendingTraceColour, 20);
        draw->AddCircle(*q, 12 * scale, IM_COL32(255, 255, 255, 255), 20, 2 * scale);
      }
  }
}

void drag_proposal_ends(AppState& app) {
  ProposalsState& s = app.mapping.proposals;
  if (!s.ends || !current(app) || !app.model_view.picker()) return;
  // A handle the thumb drags: a touch target, wider than the ring drawn.
  const float r = app.targets.target_px() / 2;
  const ImVec2 cursor = ImGui::GetCursorScreenPos();
  for (int k = 0; k < 2; ++k) {
    const auto q = app.model_view.to_screen((*s.ends)[k]);
    if (!q) continue;
    ImGui::SetCursorScreenPos(ImVec2(q->x - r, q->y - r));
    ImGui::PushID(k);
    ImGui::InvisibleButton("##proposal end", ImVec2(2 * r, 2 * r));
    // Dragged along the trace: a drag on it never scrolls (issue 27, touch).
    app.targets.record_dragged(k == 0 ? "proposal start" : "proposal end", ImGui::GetItemRectMin(),
                               ImGui::GetItemRectMax(), ImGui::GetItemID());
    if (ImGui::IsItemActivated()) s.dragging = k;
    if (ImGui::IsItemActive() && s.dragging == k) {
      const ScreenRay ray = app.model_view.ray_at(ImGui::GetIO().MousePos);
      if (const auto hit = app.model_view.picker()->pick({ray.origin, ray.direction}))
        (*s.ends)[k] = hit->point;
    }
    if (ImGui::IsItemDeactivated() && s.dragging == k) {
      s.dragging = -1;
      retrace(app);
    }
    ImGui::PopID();
  }
  ImGui::SetCursorScreenPos(cursor);
}

bool tap_proposal(AppState& app, ImVec2 tap) {
  ProposalsState& s = app.mapping.proposals;
  if (!current(app) || !app.mapping.marker.taps().empty()) return false;
  if (s.ends) return true;  // correcting: taps go to the handles only
  const float radius = std::max(kPickRadiusPx * app.targets.scale(), app.targets.target_px() / 2);
  double best = radius;
  std::optional<std::size_t> found;
  const auto& proposals = s.result->proposals;
  for (std::size_t i = 0; i < proposals.size(); ++i) {
    if (!shown(s, proposals[i])) continue;
    std::optional<ImVec2> last;
    for (const auto& x : proposals[i].trace.points) {
      const auto q = app.model_view.to_screen(x);
      if (q && last) {
        const Eigen::Vector2d a(last->x, last->y), b(q->x, q->y), p(tap.x, tap.y);
        const double t =
            std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-9), 0.0, 1.0);
        const double d = (a + t * (b - a) - p).norm();
        if (d < best) {
          best = d;
          found = i;
        }
      }
      last = q;
    }
  }
  if (!found) {
    s.selected.reset();
    s.photo_stale = true;
    return false;
  }
  s.selected = found;
  s.photo_stale = true;
  return true;
}

}  // namespace rockface::ui
