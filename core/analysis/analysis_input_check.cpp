#include "core/analysis/analysis_input_check.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "core/common/error.h"

namespace rockface::analysis {

namespace {

std::string index(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// The checks of one input, each naming the field by its path in the scene.
class InputCheck {
 public:
  explicit InputCheck(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw InputError(source_ + ": " + path, reason);
  }
  void finite(double v, const std::string& path) const {
    if (!std::isfinite(v)) fail(path, "must be finite");
  }
  void finite(const Eigen::Vector3d& v, const std::string& path) const {
    for (int k = 0; k < 3; ++k) finite(v[k], index(path, k));
  }
  void in(double v, const std::string& path, double lo, double hi, bool hi_open = false) const {
    finite(v, path);
    if (v < lo || v > hi || (hi_open && v == hi)) {
      std::ostringstream msg;
      msg << number_as_written(v) << " is outside [" << lo << ", " << hi << (hi_open ? ")" : "]");
      fail(path, msg.str());
    }
  }
  void positive(double v, const std::string& path) const {
    finite(v, path);
    if (!(v > 0)) fail(path, number_as_written(v) + " must be positive");
  }
  void non_negative(double v, const std::string& path) const {
    finite(v, path);
    if (v < 0) fail(path, number_as_written(v) + " must not be negative");
  }
  void id(const std::string& s, const std::string& path) const {
    if (s.empty()) fail(path, "must not be empty");
  }
  void orientation(double dip, double dipdir, const std::string& path) const {
    in(dip, path + ".dip", 0, 90);
    in(dipdir, path + ".dipdir", 0, 360);
  }

 private:
  const std::string& source_;
};

void check_joints(const InputCheck& c, const std::vector<SceneJoint>& joints) {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const SceneJoint& j = joints[i];
    const std::string path = index("joints", i);
    c.id(j.id, path + ".id");
    c.orientation(j.dip, j.dipdir, path);
    if (j.point) c.finite(*j.point, path + ".point");
    if (j.friction) c.in(*j.friction, path + ".friction", 0, 90, true);
    if (j.cohesion) c.in(*j.cohesion, path + ".cohesion", 0, kMaxJointCohesionPa);
  }
}

void check_free_faces(const InputCheck& c, const std::vector<SceneFreeFace>& faces) {
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const SceneFreeFace& f = faces[i];
    const std::string path = index("free_faces", i);
    c.id(f.id, path + ".id");
    c.orientation(f.dip, f.dipdir, path);
    if (f.point) c.finite(*f.point, path + ".point");
    if (f.rock_side != 0 && f.rock_side != 1)
      c.fail(path + ".rock_side",
             std::to_string(f.rock_side) + " is neither 0 (\"upper\") nor 1 (\"lower\")");
  }
}

void check_blocks(const InputCheck& c, const std::vector<SceneBlock>& blocks) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const SceneBlock& b = blocks[i];
    const std::string path = index("blocks", i);
    c.id(b.id, path + ".id");
    const bool vertex_form = !b.vertices.empty() || !b.faces.empty();
    if (b.has_halfspaces() == vertex_form)
      c.fail(path, "give either \"halfspaces\" or \"vertices\" + \"faces\"");
    for (const auto& [plane, code] : b.halfspaces)
      if (code != 0 && code != 1)
        c.fail(path + ".halfspaces." + plane,
               std::to_string(code) + " is neither \"upper\" nor \"lower\"");
    for (std::size_t k = 0; k < b.vertices.size(); ++k)
      c.finite(b.vertices[k], index(path + ".vertices", k));
    for (std::size_t k = 0; k < b.faces.size(); ++k) {
      const std::string fpath = index(path + ".faces", k);
      c.id(b.faces[k].plane, fpath + ".plane");
      const std::vector<int>& loop = b.faces[k].loop;
      if (loop.size() < 3) c.fail(fpath + ".loop", "needs at least 3 vertices");
      for (std::size_t m = 0; m < loop.size(); ++m)
        if (loop[m] < 0 || loop[m] >= static_cast<int>(b.vertices.size()))
          c.fail(index(fpath + ".loop", m), "vertex index " + std::to_string(loop[m]) +
                                                " is out of range (block has " +
                                                std::to_string(b.vertices.size()) + " vertices)");
    }
  }
}

void check_points(const InputCheck& c, const std::vector<Eigen::Vector3d>& points,
                  const std::string& path) {
  for (std::size_t k = 0; k < points.size(); ++k) c.finite(points[k], index(path, k));
}

void check_surface(const InputCheck& c, const AnalysisInput& in) {
  for (std::size_t i = 0; i < in.patches.size(); ++i) {
    const std::string path = index("surface.patches", i);
    c.id(in.patches[i].id, path + ".id");
    check_points(c, in.patches[i].polygon, path + ".polygon");
    if (in.patches[i].polygon.size() < 3) c.fail(path + ".polygon", "needs at least 3 points");
  }
  // A trace with fewer than two points is let through: the trace network
  // refuses it with its own message and the rest of the map goes on.
  for (std::size_t i = 0; i < in.traces.size(); ++i) {
    const std::string path = index("traces", i);
    c.id(in.traces[i].id, path + ".id");
    if (in.traces[i].joint) c.id(*in.traces[i].joint, path + ".joint");
    check_points(c, in.traces[i].points, path + ".points");
  }
}

void check_dynamics(const InputCheck& c, const SceneDynamics& d) {
  const std::string p = "analysis.dynamics";
  c.in(d.duration_s, p + ".duration_s", 1e-3, 600);
  c.positive(d.sample_s, p + ".sample_s");
  if (d.duration_s / d.sample_s > 100000)
    c.fail(p + ".sample_s", "more than 100000 samples over duration_s");
  if (d.abs_tol) c.in(*d.abs_tol, p + ".abs_tol", 1e-15, 1e-2);
  if (d.rel_tol) c.in(*d.rel_tol, p + ".rel_tol", 1e-14, 1e-2);
  if (d.max_step_s) c.in(*d.max_step_s, p + ".max_step_s", 1e-6, 1);
  if (d.floor) {
    const std::string fp = p + ".floor";
    c.finite(d.floor->point, fp + ".point");
    c.in(d.floor->dip, fp + ".dip", 0, 90, true);
    c.in(d.floor->dipdir, fp + ".dipdir", 0, 360);
  }
}

void check_analysis(const InputCheck& c, const SceneAnalysis& a) {
  const std::string p = "analysis";
  if (a.remote_axis && a.remote_axis->starts &&
      (*a.remote_axis->starts < 1 || *a.remote_axis->starts > 100000))
    c.fail(p + ".remote_axis.starts", "must be between 1 and 100000");
  if (a.stability != "limit_equilibrium" && a.stability != "equilibrium_path" &&
      a.stability != "none")
    c.fail(p + ".stability",
           "\"" + a.stability + "\" is not limit_equilibrium, equilibrium_path or none");
  c.in(a.orientation_uncertainty_deg, p + ".orientation_uncertainty_deg", 0, 45);
  if (a.reference_mass) c.positive(*a.reference_mass, p + ".reference_mass");
  c.non_negative(a.snap_tolerance, p + ".snap_tolerance");
  // A micrometre (coordinates to six decimals) to a metre (a point paced
  // out): finer is below what any survey states, coarser moves planes by
  // more than a block's joints are apart.
  c.in(a.survey_precision_m, p + ".survey_precision_m", 1e-6, 1);
  if (a.contact_density && (*a.contact_density < 1 || *a.contact_density > 64))
    c.fail(p + ".contact_density", "must be between 1 and 64 sub-divisions per edge");
  if (a.continuation_step) c.in(*a.continuation_step, p + ".continuation_step", 1e-6, 10);
  if (a.max_steps && (*a.max_steps < 1 || *a.max_steps > 100000))
    c.fail(p + ".max_steps", "must be between 1 and 100000");
  if (a.lambda_max) c.in(*a.lambda_max, p + ".lambda_max", 0.1, 1e6);
  if (a.dynamics) check_dynamics(c, *a.dynamics);
}

void check_joint_law(const InputCheck& c, const SceneJointLaw& law) {
  const std::string lp = "effects.joint_law";
  if (law.model != "barton_bandis" && law.model != "grasselli" && law.model != "coulomb")
    c.fail(lp + ".model", "\"" + law.model + "\" is not barton_bandis, grasselli or coulomb");
  c.in(law.jrc, lp + ".jrc", 0, 20);
  c.positive(law.jcs, lp + ".jcs");
  c.in(law.phi_b, lp + ".phi_b", 0, 90, true);
  c.positive(law.normal_stiffness, lp + ".normal_stiffness");
  c.in(law.poisson_ratio, lp + ".poisson_ratio", -0.99, 0.49);
  if (law.phi_r) c.in(*law.phi_r, lp + ".phi_r", 0, 90, true);
  c.positive(law.lab_length, lp + ".lab_length");
  if (law.field_length) c.positive(*law.field_length, lp + ".field_length");
}

void check_effects(const InputCheck& c, const SceneEffects& e) {
  const std::string p = "effects";
  if (e.water) {
    const std::string wp = p + ".water";
    c.positive(e.water->unit_weight, wp + ".unit_weight");
    c.finite(e.water->phreatic_point, wp + ".phreatic_surface.point");
    c.orientation(e.water->phreatic_dip, e.water->phreatic_dipdir, wp + ".phreatic_surface");
    for (std::size_t k = 0; k < e.water->joints.size(); ++k)
      c.id(e.water->joints[k], index(wp + ".joints", k));
  }
  if (e.seismic) c.finite(*e.seismic, p + ".seismic.acceleration");
  if (e.insitu_stress) {
    const std::string sp = p + ".insitu_stress.tensor";
    const Eigen::Matrix3d& m = *e.insitu_stress;
    for (int i = 0; i < 3; ++i) c.finite(Eigen::Vector3d(m.row(i).transpose()), index(sp, i));
    if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, m.cwiseAbs().maxCoeff()))
      c.fail(sp, "must be symmetric");
  }
  for (std::size_t k = 0; k < e.forces.size(); ++k) {
    const std::string fp = index(p + ".forces", k);
    c.finite(e.forces[k].vector, fp + ".vector");
    c.finite(e.forces[k].point, fp + ".point");
    if (e.forces[k].frame != "space" && e.forces[k].frame != "block")
      c.fail(fp + ".frame", "\"" + e.forces[k].frame + "\" is neither \"space\" nor \"block\"");
  }
  for (std::size_t k = 0; k < e.bolts.size(); ++k) {
    const std::string bp = index(p + ".bolts", k);
    c.finite(e.bolts[k].point, bp + ".point");
    c.in(e.bolts[k].trend, bp + ".trend", 0, 360);
    c.in(e.bolts[k].plunge, bp + ".plunge", -90, 90);
    c.non_negative(e.bolts[k].force, bp + ".force");
  }
  if (e.joint_law) check_joint_law(c, *e.joint_law);
}

// Across fields: ids unique, and every plane or joint id referred to known.
void check_references(const InputCheck& c, const AnalysisInput& in) {
  std::set<std::string> planes;
  for (std::size_t i = 0; i < in.joints.size(); ++i)
    if (!planes.insert(in.joints[i].id).second)
      c.fail(index("joints", i) + ".id", "duplicate id \"" + in.joints[i].id + "\"");
  for (std::size_t i = 0; i < in.free_faces.size(); ++i)
    if (!planes.insert(in.free_faces[i].id).second)
      c.fail(index("free_faces", i) + ".id", "duplicate id \"" + in.free_faces[i].id + "\"");
  auto check_ids = [&](const auto& items, const char* what) {
    std::set<std::string> ids;
    for (std::size_t i = 0; i < items.size(); ++i)
      if (!ids.insert(items[i].id).second)
        c.fail(index(what, i) + ".id", "duplicate id \"" + items[i].id + "\"");
  };
  check_ids(in.blocks, "blocks");
  check_ids(in.patches, "surface.patches");
  check_ids(in.traces, "traces");
  for (std::size_t i = 0; i < in.blocks.size(); ++i) {
    const std::string path = index("blocks", i);
    for (const auto& [id, code] : in.blocks[i].halfspaces)
      if (!planes.count(id)) c.fail(path + ".halfspaces." + id, "unknown plane id \"" + id + "\"");
    for (std::size_t k = 0; k < in.blocks[i].faces.size(); ++k)
      if (!planes.count(in.blocks[i].faces[k].plane))
        c.fail(index(path + ".faces", k) + ".plane",
               "unknown plane id \"" + in.blocks[i].faces[k].plane + "\"");
  }
  for (std::size_t i = 0; i < in.traces.size(); ++i)
    if (in.traces[i].joint && !in.joint(*in.traces[i].joint))
      c.fail(index("traces", i) + ".joint", "unknown joint id \"" + *in.traces[i].joint + "\"");
  if (in.effects.water)
    for (std::size_t k = 0; k < in.effects.water->joints.size(); ++k)
      if (!in.joint(in.effects.water->joints[k]))
        c.fail(index("effects.water.joints", k),
               "unknown joint id \"" + in.effects.water->joints[k] + "\"");
}

}  // namespace

void check_analysis_input(const AnalysisInput& in) {
  const InputCheck c(in.source);
  c.finite(in.datum, "datum");
  c.positive(in.density, "rock.density");
  c.finite(in.gravity, "gravity");
  check_joints(c, in.joints);
  check_free_faces(c, in.free_faces);
  check_blocks(c, in.blocks);
  check_surface(c, in);
  check_analysis(c, in.analysis);
  check_effects(c, in.effects);
  check_references(c, in);
}

int rock_side_code(const std::string& word, const std::string& where) {
  if (word == "upper") return 0;
  if (word == "lower") return 1;
  throw InputError(where, "\"" + word + "\" is neither \"upper\" nor \"lower\"");
}

std::string number_as_written(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "NaN" : (v > 0 ? "Infinity" : "-Infinity");
  // A whole number as a JSON integer is written ("95", not "95.0").
  if (v == std::trunc(v) && std::fabs(v) < 1e15) {
    std::ostringstream whole;
    whole << static_cast<long long>(v);
    return whole.str();
  }
  // nlohmann's layout of the shortest digits that read back as `v`: plain
  // from 1e-4 up to 1e15, else d.ddde+XX with at least two exponent digits.
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  std::string sci(buf, end);
  std::string sign;
  if (sci[0] == '-') {
    sign = "-";
    sci.erase(0, 1);
  }
  const std::size_t e = sci.find('e');
  std::string digits = sci.substr(0, e);
  if (digits.size() > 1) digits.erase(1, 1);  // the '.'
  const int exponent = std::atoi(sci.c_str() + e + 1);
  const int k = static_cast<int>(digits.size());
  const int n = exponent + 1;  // where the decimal point goes
  if (k <= n && n <= 15) return sign + digits + std::string(n - k, '0') + ".0";
  if (0 < n && n <= 15) return sign + digits.substr(0, n) + "." + digits.substr(n);
  if (-4 < n && n <= 0) return sign + "0." + std::string(-n, '0') + digits;
  std::string out = sign + digits.substr(0, 1);
  if (k > 1) out += "." + digits.substr(1);
  const int x = n - 1;
  std::string ex = std::to_string(std::abs(x));
  if (ex.size() < 2) ex = "0" + ex;
  return out + "e" + (x < 0 ? "-" : "+") + ex;
}

}  // namespace rockface::analysis
