#pragma once
// The constitutive law of a rock joint at one contact point: normal and
// shear tractions from the relative displacement of the block against the
// rock, given the joint's history. One interface, so that a future law
// plugs in beside the staged Barton-Bandis / Grasselli law and the
// elastic-perfectly plastic Coulomb law (make_joint_law).
//
// Springs in series: the relative displacement is the elastic part of the
// normal and shear springs plus the joint's own slip (shear) and dilation
// (normal). A very stiff joint (1e12 Pa/m) makes the elastic part vanish:
// the law becomes rigid-plastic.
//
// Signs: compression positive (rock mechanics). closure > 0 presses the
// block onto the rock; the normal stress acts on the block along the
// joint's block-side normal. The shear stress is the spring's, along the
// shear displacement: it acts on the block against it.
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

namespace rockface::mechanics {

// A joint's history at one contact point.
struct JointState {
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();  // plastic shear displacement, m (joint frame)
  double slip_length = 0;       // accumulated length of the slip path, m (stage B)
  double work = 0;              // shear energy dissipated after the peak, J/m^2 (stage C)
  double dilation = 0;          // normal opening from riding on asperities, m (>= 0)
  double softening_energy = 0;  // J/m^2 of stage C, fixed when the peak is reached
  bool past_peak = false;
};

// Where a contact is on its law.
enum class JointStage {
  Open,      // no contact: no tractions
  Elastic,   // stage A: springs only
  PrePeak,   // stage B: slipping towards the peak, dilation growing
  PostPeak,  // stage C: softening with the dissipated energy (or perfectly plastic)
};
const char* stage_name(JointStage s);

struct JointResponse {
  double normal_stress = 0;                                // Pa, compression positive
  Eigen::Vector2d shear_stress = Eigen::Vector2d::Zero();  // Pa, along the shear displacement
  JointStage stage = JointStage::Open;
  bool slipping = false;  // the strength was reached in this step
  JointState state;       // after the step (commit it when the step is accepted)
  // The consistent tangent of this response (the derivatives of the
  // tractions above, return mapping included, from the same committed
  // state): d(normal_stress, shear_stress) / d(closure, shear), Pa/m, and
  // d(normal_stress, shear_stress) / d(strength_divisor), Pa. Path
  // following uses them instead of differences.
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();
  Eigen::Vector3d divisor_rate = Eigen::Vector3d::Zero();
};

class JointLaw {
 public:
  virtual ~JointLaw() = default;
  virtual std::string name() const = 0;
  virtual double normal_stiffness() const = 0;  // Pa/m
  virtual double shear_stiffness() const = 0;   // Pa/m
  // The shear displacement over which the strength develops (m): the peak
  // displacement of a staged law, 0 for a law that is elastic-perfectly
  // plastic. Path following scales its steps to it.
  virtual double slip_scale() const { return 0; }
  // Shear strength (Pa) at normal stress sigma_n in the history `state`,
  // before any reduction.
  virtual double strength(double sigma_n, const JointState& state) const = 0;
  // Tractions for the total displacement (closure, shear) reached from the
  // committed state. strength_divisor > 0 divides the shear strength (the
  // strength-reduction load factor); <= 0 means no slip at all.
  virtual JointResponse respond(const JointState& committed, double closure,
                                const Eigen::Vector2d& shear, double strength_divisor) const = 0;
};

enum class JointModel { BartonBandis, Grasselli, Coulomb };

// Everything a law may need; angles in radians, SI units. The scene's
// effects.joint_law fills it (docs/scene-extensions.md).
struct JointLawParameters {
  JointModel model = JointModel::BartonBandis;
  double normal_stiffness = 1e10;  // Pa/m
  double poisson_ratio = 0.25;     // shear stiffness = kn / (2 (1 + nu))
  // Barton-Bandis peak
  double jrc = 10;                     // joint roughness coefficient, [0, 20]
  double jcs = 1e8;                    // joint wall compressive strength, Pa
  double phi_b = 0.5235987755982988;   // basic friction angle (30 degrees)
  std::optional<double> phi_r;         // residual friction angle; default phi_b
  double lab_length = 0.1;             // m, sample length L0 of JRC and JCS
  std::optional<double> field_length;  // m, in-situ length Ln: scale corrections when given
  // Grasselli peak (Grasselli & Egger 2003)
  double contact_area = 0.5;              // A0, maximum contact area ratio, (0, 1]
  double theta_max = 1.0471975511965976;  // theta*max, maximum apparent dip, radians (60 deg)
  double roughness_c = 5;                 // C, roughness parameter (> 0)
  double tensile_strength = 1e7;          // sigma_t of the intact rock, Pa
  // Stages B and C
  bool dilation = true;                    // false: no dilation in any stage
  double dilation_divisor = 2;             // M: dilation angle = mobilised roughness / M
  std::optional<double> softening_energy;  // J/m^2; default 9 / ln 2 x delta_peak x tau_peak
  // Coulomb (elastic-perfectly plastic, no dilation)
  double friction = 0.5235987755982988;  // radians
  double cohesion = 0;                   // Pa
};

// Checks the parameters and builds the law. Throws InputError naming the
// field ("joint_law.jrc", "joint_law.normal_stiffness") and the reason.
std::unique_ptr<JointLaw> make_joint_law(const JointLawParameters& p);

}  // namespace rockface::mechanics
