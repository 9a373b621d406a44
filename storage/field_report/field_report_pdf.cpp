#include "storage/field_report/field_report_pdf.h"

#include <algorithm>
#include <memory>
#include <sstream>

#include <cairo-pdf.h>
#include <cairo.h>
#include <opencv2/imgproc.hpp>

#include "core/analysis/block_reading.h"
#include "core/analysis/effect_words.h"
#include "core/common/error.h"
#include "core/rockmass/figures_in_words.h"
#include "storage/field_report/dynamics_picture.h"
#include "storage/field_report/field_report_pictures.h"
#include "storage/field_report/table_layout.h"
#include "storage/project/visit_geologist.h"

namespace rockface::storage {

namespace {

// A4 in PostScript points; margins and type sizes of a printed page.
constexpr double kPageW = 595.28, kPageH = 841.89, kMargin = 48;
constexpr double kBody = 9, kSmall = 7.5, kHeading = 13, kTitle = 18;
// The smallest type a table shrinks to before its widest words overrun.
constexpr double kSmallest = 6;

// Writes text top to bottom, starting a new page when the next item does not fit.
class PdfPages {
 public:
  explicit PdfPages(const std::filesystem::path& file)
      : file_(file),
        surface_(cairo_pdf_surface_create(file.c_str(), kPageW, kPageH), cairo_surface_destroy),
        cr_(cairo_create(surface_.get()), cairo_destroy) {
    check();
  }

  void title(const std::string& text) {
    line(text, kTitle, true);
    y_ += kTitle * 0.6;
  }
  // `keep` points of what follows stay on the heading's page.
  void heading(const std::string& text, double keep = 2 * kBody) {
    space(kHeading * 2.2 + keep);  // never a heading alone at a page foot
    y_ += kHeading * 0.6;
    font(kHeading, true);
    show(kMargin, text);
    y_ += kHeading * 0.5;
  }
  // A paragraph, wrapped at spaces to the text width.
  void line(const std::string& text, double size = kBody, bool bold = false) {
    font(size, bold);
    std::string rest = text;
    while (!rest.empty()) {
      std::size_t cut = rest.size();
      while (width(rest.substr(0, cut)) > text_width()) {
        const std::size_t space_at = rest.rfind(' ', cut - 1);
        if (space_at == std::string::npos || space_at == 0) break;
        cut = space_at;
      }
      space(size * 1.45);
      font(size, bold);
      show(kMargin, rest.substr(0, cut));
      rest = cut < rest.size() ? rest.substr(cut + 1) : std::string();
    }
  }
  // A table laid out from the measured widths of its cells
  // (table_layout.h); a row that does not fit starts a new page, where the
  // header is repeated.
  void table(const std::vector<std::string>& header,
             const std::vector<std::vector<std::string>>& rows, double size = kBody) {
    const TableLayout t = lay_out_table(header, rows, text_width(), size, kSmallest,
                                        [this](const std::string& s, double points, bool bold) {
                                          font(points, bold);
                                          return width(s);
                                        });
    const double leading = t.size * 1.3;
    auto row = [&](std::size_t r) {
      std::size_t lines = 1;
      for (const auto& c : t.cells[r]) lines = std::max(lines, c.size());
      const double height = static_cast<double>(lines) * leading + 0.15 * t.size;
      const bool new_page = space(height);
      if (new_page && r > 0) show_row(t, 0, leading);
      show_row(t, r, leading);
    };
    space(2 * leading);  // never a header alone at a page foot
    for (std::size_t r = 0; r < t.cells.size(); ++r) row(r);
  }
  // An image scaled to fit `max_w` x `max_h` points, keeping its aspect.
  void image(const cv::Mat& bgr, double max_w, double max_h) {
    if (bgr.empty()) return;
    const double s = std::min(max_w / bgr.cols, max_h / bgr.rows);
    const double h = bgr.rows * s;
    space(h + 6);
    cv::Mat bgra;
    cv::cvtColor(bgr, bgra,
                 cv::COLOR_BGR2BGRA);  // cairo RGB24 is B, G, R, x in memory (little endian)
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> img(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, bgra.cols, bgra.rows),
        cairo_surface_destroy);
    cairo_surface_flush(img.get());
    unsigned char* data = cairo_image_surface_get_data(img.get());
    const int stride = cairo_image_surface_get_stride(img.get());
    for (int r = 0; r < bgra.rows; ++r)
      std::copy_n(bgra.ptr<unsigned char>(r), 4 * bgra.cols, data + r * stride);
    cairo_surface_mark_dirty(img.get());
    cairo_save(cr_.get());
    cairo_translate(cr_.get(), kMargin, y_);
    cairo_scale(cr_.get(), s, s);
    cairo_set_source_surface(cr_.get(), img.get(), 0, 0);
    cairo_paint(cr_.get());
    cairo_restore(cr_.get());
    y_ += h + 6;
  }
  void gap(double points) { y_ += points; }

  void finish() {
    cairo_show_page(cr_.get());
    cr_.reset();
    cairo_surface_finish(surface_.get());
    check();
  }
  static double text_width() { return kPageW - 2 * kMargin; }

 private:
  void check() {
    const cairo_status_t st = cairo_surface_status(surface_.get());
    if (st != CAIRO_STATUS_SUCCESS)
      throw Error(file_.string() + ": cannot write the PDF: " + cairo_status_to_string(st));
  }
  // Starts a new page when `needed` points do not fit on this one; says so.
  bool space(double needed) {
    if (y_ + needed <= kPageH - kMargin) return false;
    cairo_show_page(cr_.get());
    y_ = kMargin;
    return true;
  }
  void show_row(const TableLayout& t, std::size_t r, double leading) {
    font(t.size, r == 0);
    std::size_t lines = 1;
    for (std::size_t c = 0; c < t.cells[r].size(); ++c) {
      const auto& cell = t.cells[r][c];
      lines = std::max(lines, cell.size());
      for (std::size_t k = 0; k < cell.size(); ++k) {
        cairo_set_source_rgb(cr_.get(), 0, 0, 0);
        cairo_move_to(cr_.get(), kMargin + t.left[c], y_ + t.size + k * leading);
        cairo_show_text(cr_.get(), cell[k].c_str());
      }
    }
    y_ += static_cast<double>(lines) * leading + 0.15 * t.size;
  }
  double width(const std::string& text) {
    cairo_text_extents_t e;
    cairo_text_extents(cr_.get(), text.c_str(), &e);
    return e.x_advance;
  }
  void font(double size, bool bold) {
    cairo_select_font_face(cr_.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_.get(), size);
    size_ = size;
  }
  // Shows text with its baseline one line below the cursor; advances the
  // cursor unless `advance` is false (a table cell: the row advances).
  void show(double x, const std::string& text, bool advance = true) {
    cairo_set_source_rgb(cr_.get(), 0, 0, 0);
    cairo_move_to(cr_.get(), x, y_ + size_);
    cairo_show_text(cr_.get(), text.c_str());
    if (advance) y_ += size_ * 1.45;
  }

  std::filesystem::path file_;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_;
  double y_ = kMargin, size_ = kBody;
};

// A text with each absolute path in it cut to its file name: the page is
// read on another machine, and the project's folder is no one's business
// there ("replay /home/geo/scenes/face.scene.json" -> "replay face.scene.json").
std::string file_names_only(const std::string& text) {
  std::string out, word;
  std::istringstream words(text);
  while (words >> word) {
    if (word.size() > 1 && word[0] == '/' && word.find('/', 1) != std::string::npos)
      word = std::filesystem::path(word).filename().string();
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

// What the stereonet draws, in the words a geologist reads it by.
std::string stereonet_caption(const FieldReport& r) {
  std::string s =
      "dots: poles of the joints (grey: in no set), thin lines: their great circles; sets: mean "
      "pole (square), great circle, 95 % confidence cone of the mean and, thin, the cone of 95 % "
      "of the set's poles";
  if (!r.face_planes.empty())
    s += "; black, listed at the foot: the great circles of the face's planes";
  const auto phi = stereonet_friction_deg(r);
  if (phi)
    s += "; red: the friction circle of the weakest joint (" + report_number(*phi, 1) +
         " deg), poles inside it dip less than it";
  if (const auto* face = stereonet_face(r); face && phi)
    s += "; the face " + face->label + " (" + report_number(face->dip_deg, 0) + "/" +
         report_number(face->dipdir_deg, 0) +
         ") in red with its daylight envelope; shaded: poles of planes that daylight in it and "
         "slide (Markland)";
  return s;
}

std::string code_text(const std::string& code) {
  const auto n = std::count(code.begin(), code.end(), '+');
  return n == 0 ? code : code.substr(0, code.find('+')) + " +" + std::to_string(n);
}

// What the visit does not have is said, never printed as a zero ("0 x 0 px,
// fx 0.0" for a visit made by `rockface measure`, which has no photographs
// of its own; issue 41).
constexpr const char* kNotKnown = "not known";

void camera_section(PdfPages& pdf, const FieldReport& r) {
  pdf.heading("Camera and preset");
  const auto& k = r.intrinsics;
  pdf.line("camera: " + (r.camera_body.empty() ? std::string("unknown") : r.camera_body) +
           (r.lens.empty() ? "" : ", lens " + r.lens));
  if (r.calibration_known)
    pdf.line("calibration: " + (r.calibration_method.empty() ? "-" : r.calibration_method) + "; " +
             std::to_string(k.width) + " x " + std::to_string(k.height) + " px, fx " +
             report_number(k.fx, 1) + ", fy " + report_number(k.fy, 1) + ", cx " +
             report_number(k.cx, 1) + ", cy " + report_number(k.cy, 1) + " px, rms " +
             report_number(k.rms_px, 2) + " px");
  else
    pdf.line(std::string("calibration: ") + kNotKnown +
             (r.photograph.empty() ? " (no photographs in this visit)" : ""));
  pdf.line("preset: " + (r.preset.empty() ? std::string(kNotKnown) : r.preset));
}

// The precision line of a reconstruction: the parts its record states, in
// their usual order; "not known" when it states none.
std::string precision_text(const ReportedAccuracy& a) {
  std::vector<std::string> parts;
  if (a.sigma_z_m)
    parts.push_back("predicted depth precision " + report_number(*a.sigma_z_m * 1000, 1) + " mm" +
                    (a.distance_m ? " at " + report_number(*a.distance_m, 2) + " m" : ""));
  if (a.point_spacing_m)
    parts.push_back("point spacing " + report_number(*a.point_spacing_m * 1000, 1) + " mm");
  std::string pair;
  if (a.tie_points) pair = std::to_string(*a.tie_points) + " tie points";
  if (a.reprojection_rms_px)
    pair += (pair.empty() ? "" : ", ") + std::string("reprojection rms ") +
            report_number(*a.reprojection_rms_px, 3) + " px";
  if (!pair.empty()) parts.push_back(pair);
  if (parts.empty())
    return std::string("predicted depth precision, point spacing and tie points: ") + kNotKnown +
           " (no 3D image reconstructed in this visit)";
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : "; ") + p;
  return out;
}

void accuracy_section(PdfPages& pdf, const FieldReport& r) {
  const auto& a = r.accuracy;
  pdf.heading("Accuracy");
  if (!a.imported_from.empty()) pdf.line("3D image imported from " + a.imported_from);
  pdf.line("scale: " + (a.scale_source.empty() ? std::string(kNotKnown) : a.scale_source) +
           (a.range_pole_m ? " (" + report_number(*a.range_pole_m, 3) + " m)" : "") +
           (a.scale ? ", model scale " + report_number(*a.scale, 4) : ""));
  pdf.line("vertical: " + (a.vertical_source.empty() ? std::string(kNotKnown) : a.vertical_source));
  std::string north =
      "north: " + (a.north_source.empty() ? std::string(kNotKnown) : a.north_source);
  if (a.compass_azimuth_deg)
    north += ", reference line bearing " + report_number(*a.compass_azimuth_deg, 1) +
             " deg, declination " + report_number(a.declination_deg, 1) + " deg, turned " +
             report_number(a.north_rotation_deg, 2) + " deg about the vertical";
  pdf.line(north);
  if (!a.imported_from.empty())
    pdf.line("point spacing " +
             (a.point_spacing_m ? report_number(*a.point_spacing_m * 1000, 1) + " mm"
                                : std::string(kNotKnown)) +
             " (no stereo pair: no predicted depth precision, no tie points)");
  else
    pdf.line(precision_text(a));
  if (a.control_rms_m) {
    pdf.line("ground control: rms " + report_number(*a.control_rms_m * 1000, 1) + " mm");
    std::vector<std::vector<std::string>> rows;
    for (const auto& p : a.control_points)
      rows.push_back({p.id, report_number(p.residual_m * 1000, 1)});
    pdf.table({"point", "residual mm"}, rows);
  } else {
    pdf.line("ground control: none");
  }
  if (!a.images.empty()) {
    pdf.line("3D images of the face: " + std::to_string(a.images.size()));
    std::vector<std::vector<std::string>> rows;
    for (const auto& i : a.images)
      rows.push_back({i.name, i.role, i.reference.empty() ? "-" : i.reference,
                      i.role == "master" ? "-" : std::to_string(i.tie_points),
                      i.role == "master" ? "-" : report_number(i.overlap * 100, 0),
                      i.role == "master" ? "-" : report_number(i.surface_rms_m * 1000, 1),
                      report_number(i.scale, 4)});
    pdf.table({"image", "role", "tied to", "tie points", "overlap %", "surface rms mm", "scale"},
              rows);
  }
  for (const auto& w : a.warnings) pdf.line("warning: " + w, kSmall);
}

void tunnel_section(PdfPages& pdf, const FieldReport& r) {
  if (!r.tunnel) return;
  const ReportedTunnel& t = *r.tunnel;
  pdf.heading("The tunnel", 0.35 * kPageH);
  pdf.line("tunnel " + t.name + ": chainage " + report_number(t.first_chainage, 2) + " to " +
           report_number(t.last_chainage, 2) + " m, drive " + t.drive);
  pdf.line("design profile " + (t.profile_name.empty() ? std::string("-") : t.profile_name) + ": " +
           report_number(t.perimeter_m, 2) + " m around, " + report_number(t.area_m2, 2) +
           " m²; underbreak tolerance " + report_number(t.underbreak_tolerance_m * 100, 0) + " cm");
  if (!t.placement) {
    pdf.line("this visit is not placed in the tunnel");
  } else {
    const auto& p = *t.placement;
    pdf.line("face at chainage " + report_number(p.chainage, 2) + ", offset " +
             report_number(p.offset_m, 2) + " m; placed by " +
             (p.method == VisitPlacement::Method::ground_control
                  ? std::string("monitoring targets with survey coordinates")
                  : std::string("the typed chainage and the compass line")) +
             (p.note.empty() ? "" : " (" + p.note + ")"));
    if (p.rms_m) pdf.line("target residual rms " + report_number(*p.rms_m * 1000, 1) + " mm");
    std::vector<std::vector<std::string>> rows;
    for (const auto& res : p.residuals)
      rows.push_back({res.label, report_number(res.residual.norm() * 1000, 1)});
    if (!rows.empty()) pdf.table({"target", "residual mm"}, rows);
  }
  for (const auto& line : t.profile_lines) pdf.line(line, kSmall);
  if (!t.developed_view.empty()) {
    pdf.image(t.developed_view, PdfPages::text_width(), 0.4 * kPageH);
    pdf.line("developed view of the round: overbreak red, underbreak blue, not seen hatched",
             kSmall);
  }
  if (!t.planes.empty()) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& pl : t.planes)
      rows.push_back({pl.label, report_number(pl.dip_deg, 1), report_number(pl.dipdir_deg, 1),
                      report_number(pl.chainage, 2), report_number(pl.offset_m, 2),
                      pl.strike_class + (pl.marginal ? " ?" : ""),
                      std::to_string(pl.rmr_adjustment), report_number(pl.margin_deg, 1)});
    pdf.table({"plane", "dip deg", "dip dir deg", "chainage", "offset m",
               "against the drive (RMR89)", "RMR adj", "margin deg"},
              rows, kSmall);
  }
  if (!t.blocks.empty()) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& b : t.blocks)
      rows.push_back({b.label, report_number(b.survey.x(), 3), report_number(b.survey.y(), 3),
                      report_number(b.survey.z(), 3), report_number(b.chainage, 2),
                      report_number(b.offset_m, 2), report_number(b.height_m, 2)});
    pdf.table({"block", "easting", "northing", "elevation", "chainage", "offset m", "height m"},
              rows, kSmall);
  }
}

void joint_section(PdfPages& pdf, const FieldReport& r) {
  pdf.heading("Joints");
  std::vector<std::vector<std::string>> rows;
  for (const auto& j : r.joints)
    rows.push_back({j.label, report_number(j.dip_deg, 1), report_number(j.dipdir_deg, 1),
                    report_number(j.friction_deg, 1), report_number(j.cohesion_pa, 0),
                    j.set_label.empty() ? "-" : j.set_label, j.source});
  pdf.table({"joint", "dip deg", "dip dir deg", "friction deg", "cohesion Pa", "set", "source"},
            rows);
  // Issue 27: a plane read with a compass on the tablet, not fitted.
  if (std::any_of(r.joints.begin(), r.joints.end(),
                  [](const auto& j) { return j.source.find("(compass)") != std::string::npos; }))
    pdf.line(
        "(compass): the dip and dip direction read with a compass on the joint where the "
        "trace runs; the trace is checked to lie in that plane");
  pdf.heading("Joint sets");
  if (r.sets.empty()) {
    pdf.line("no set: fewer than two joints, or none close enough to form one");
    return;
  }
  rows.clear();
  for (const auto& s : r.sets)
    rows.push_back({s.label, std::to_string(s.count), report_number(s.dip_deg, 1),
                    report_number(s.dipdir_deg, 1), report_number(s.fisher_k, 1),
                    report_number(s.alpha95_deg, 1), s.origin});
  pdf.table({"set", "joints", "dip deg", "dip dir deg", "Fisher K", "alpha95 deg", "from"}, rows);
}

void block_section(PdfPages& pdf, const FieldReport& r) {
  pdf.heading("Blocks");
  if (!r.analysis_id) {
    pdf.line("no block analysis stored for this visit");
    return;
  }
  pdf.line("effects simulated: " + analysis::effects_in_words(r.effects));
  std::vector<std::vector<std::string>> rows;
  for (const auto& b : r.blocks)
    rows.push_back({b.id, b.source, code_text(b.code), report_number(b.volume, 3),
                    report_number(b.mass, 0), report_verdict(b), report_number(b.margin_deg, 2),
                    report_mode(b), report_number(b.fos, 2), report_rotation(b)});
  pdf.table({"block", "source", "code", "volume m³", "mass kg", "verdict", "margin deg", "mode",
             "FoS", "rotation"},
            rows, kSmall);
  pdf.line(
      "verdict '?': marginal (the margin is within the orientation uncertainty); FoS '-': "
      "the block does not slide under the resultant or has no friction given",
      kSmall);
}

// The motion after failure of each block the analysis set moving
// (analysis.dynamics): why, its events, the landing and the picture.
void dynamics_section(PdfPages& pdf, const FieldReport& r) {
  bool any = false;
  for (const auto& b : r.blocks) any = any || b.dynamics.has_value();
  if (!any) return;
  pdf.heading("Motion after failure", 0.45 * kPageH);
  for (const auto& b : r.blocks) {
    if (!b.dynamics) continue;
    // The picture in the project frame, as the face picture (datum subtracted).
    const analysis::ReportDynamics d = analysis::relative_to(*b.dynamics, r.datum);
    std::string friction;
    for (const auto& [plane, deg] : d.friction_deg)
      friction += (friction.empty() ? "" : ", ") + plane + " " + report_number(deg, 1) + " deg";
    pdf.line("block " + b.id + ": " + d.trigger + "; friction while sliding " + friction +
             ", cohesion lost; " + d.outcome);
    std::string events;
    for (const auto& e : d.events) events += (events.empty() ? "" : "; ") + analysis::event_text(e);
    pdf.line(events, kSmall);
    if (d.landing)
      pdf.line(
          "lands at " + report_number(d.landing->time_s, 2) + " s, " +
              report_number(d.landing->speed, 1) + " m/s, kinetic energy " +
              report_number(
                  (d.landing->kinetic_translational + d.landing->kinetic_rotational) / 1000, 0) +
              " kJ, " + report_number(d.landing->distance_from_start, 1) +
              " m from where it started",
          kSmall);
    pdf.image(dynamics_picture(b.id, analysis::relative_to(b.vertices, r.datum), d),
              PdfPages::text_width(), 0.4 * kPageH);
  }
}

void wedges_section(PdfPages& pdf, const FieldReport& r) {
  if (!r.wedges) return;
  const ReportedWedges& w = *r.wedges;
  pdf.heading("Wedges around the excavation", 0.3 * kPageH);
  for (const auto& line : w.lines) pdf.line(line);
  if (w.rows.empty())
    pdf.line("no removable wedge");
  else
    pdf.table({"wedge", "place", "code", "volume m³", "weight kN", "apex m", "bolt m", "margin deg",
               "mode", "FoS", "supported"},
              w.rows, kSmall);
  for (const auto& note : w.notes) pdf.line(note, kSmall);
  if (!w.picture.empty()) {
    pdf.image(w.picture, 0.8 * PdfPages::text_width(), 0.6 * kPageH);
    pdf.line(
        "the wedges seen along the drive, and the largest in perspective; apex: height above "
        "the chord of the wedge's face; bolt: length from the excavation to the apex",
        kSmall);
  }
}

// The rock mass (issue 23): the figures in words, then RMR89 and Q line by
// line, each rating with its source (measured / entered) and its table.
void rock_mass_section(PdfPages& pdf, const FieldReport& r) {
  if (!r.rockmass && r.rockmass_note.empty()) return;
  pdf.heading("The rock mass", 0.25 * kPageH);
  if (!r.rockmass) {
    pdf.line(r.rockmass_note);
    return;
  }
  for (const auto& line : rockmass::figures_lines(*r.rockmass)) pdf.line(line, kSmall);
  pdf.heading("Classification (RMR89, Q)", 0.2 * kPageH);
  for (const auto& line : rockmass::classification_lines(*r.rockmass)) {
    const bool total = line.rfind("RMR89", 0) == 0 || line.rfind("Q ", 0) == 0;
    pdf.line(line, total ? kBody : kSmall, total);
  }
}

// Facets proposed on the 3D image (issue 25): the sets they form and the
// picture of them over the photograph.
void facets_section(PdfPages& pdf, const FieldReport& r) {
  if (!r.facets) return;
  const ReportedFacets& f = *r.facets;
  pdf.heading("Facets on the 3D image (proposed)", 0.3 * kPageH);
  for (const auto& line : f.lines) pdf.line(line);
  if (f.rows.empty())
    pdf.line("no joint set from the facets");
  else
    pdf.table(
        {"set", "dip/dir deg", "facets", "planes", "Fisher K", "a95 deg", "spacing m", "area m²"},
        f.rows, kSmall);
  for (const auto& note : f.notes) pdf.line(note, kSmall);
  if (!f.picture.empty()) {
    pdf.image(f.picture, PdfPages::text_width(), 0.5 * kPageH);
    pdf.line("facets coloured by set, grey: in no set; proposals until accepted by picks", kSmall);
  }
}

// The support of this round (issue 44): the proposals side by side, the Q
// chart with the visit's point, the checks on the wedges and blocks, the
// decision.
void support_section(PdfPages& pdf, const FieldReport& r) {
  if (!r.support) return;
  const ReportedSupport& s = *r.support;
  pdf.heading("Support of this round", 0.3 * kPageH);
  for (const auto& line : s.proposals) pdf.line(line, kSmall);
  if (!s.chart.empty()) {
    pdf.image(s.chart, 0.7 * PdfPages::text_width(), 0.4 * kPageH);
    pdf.line("the Q-system support chart with the visit's point (a ring: marginal)", kSmall);
  }
  for (const auto& line : s.checks) pdf.line(line, kSmall);
  if (!s.rows.empty() && !s.rows_pattern.empty())
    pdf.line("each wedge and block under " + s.rows_pattern, kSmall);
  if (!s.rows.empty())
    pdf.table({"wedge/block", "place", "mode", "FoS", "supported", "bolts", "needs m", "below"},
              s.rows, kSmall);
  pdf.heading("Decision", 3 * kBody);
  for (const auto& line : s.decision) pdf.line(line);
}

}  // namespace

void write_field_report_pdf(const FieldReport& r, const std::filesystem::path& file) {
  PdfPages pdf(file);
  pdf.title("Field report: " + r.project_name);
  pdf.line("visit " + std::to_string(r.visit_id) + ", started " + r.visit_started_at + " (" +
           file_names_only(r.visit_source) + ")");
  // Who mapped it (issue 46), said also when nobody was named.
  pdf.line("geologist: " + r.visit_geologist.value_or(kGeologistNotRecorded));
  pdf.line("project " + std::filesystem::path(r.project_file).filename().string() + "; datum E " +
           report_number(r.datum.x(), 3) + ", N " + report_number(r.datum.y(), 3) + ", Z " +
           report_number(r.datum.z(), 3));
  camera_section(pdf, r);
  accuracy_section(pdf, r);
  tunnel_section(pdf, r);
  wedges_section(pdf, r);

  pdf.heading("The face", 0.3 * kPageH);
  if (r.photograph.empty()) {
    pdf.line("no photograph stored for this visit");
  } else {
    pdf.image(face_picture(r), PdfPages::text_width(), 0.55 * kPageH);
    pdf.line("traces yellow; blocks: removable red, marginal orange, keyed green", kSmall);
  }
  for (const auto& outline : r.face_outlines) pdf.line(outline, kSmall);
  if (r.traces_proposed + r.traces_corrected > 0)
    pdf.line(std::to_string(r.traces_by_hand + r.traces_proposed + r.traces_corrected) +
                 " traces: " + std::to_string(r.traces_by_hand) + " tapped by hand, " +
                 std::to_string(r.traces_proposed) + " proposed and accepted, " +
                 std::to_string(r.traces_corrected) + " proposed and corrected",
             kSmall);
  pdf.heading("Stereonet (lower hemisphere, equal area)", 0.6 * PdfPages::text_width());
  const cv::Mat net = stereonet_picture(r);
  if (net.empty())
    pdf.line("no joints");
  else {
    pdf.image(net, 0.6 * PdfPages::text_width(), 0.6 * PdfPages::text_width());
    pdf.line(stereonet_caption(r), kSmall);
  }
  joint_section(pdf, r);
  block_section(pdf, r);
  dynamics_section(pdf, r);
  // After the blocks: page 1 keeps the face with its traces and blocks.
  rock_mass_section(pdf, r);
  support_section(pdf, r);
  facets_section(pdf, r);
  pdf.finish();
}

}  // namespace rockface::storage
