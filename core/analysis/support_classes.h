#pragma once
// The designer's excavation and support classes (issue 44) and the match of
// a visit against them: each class with its round length, bolt pattern,
// shotcrete, mesh, steel sets and face support, and its criteria in
// rockface's figures (RMR89 and Q ranges, the face's behaviour, the size of
// the wedges around the excavation). The classes come from the designer's
// file (storage/support/support_classes_file.h reads and refuses it); this
// file only holds and matches them.
//
// A class is proposed when every criterion it states is met by the visit's
// figures. A figure near a range's end (RMR within kRmrClassMarginalPoints,
// Q within 10 %: core/rockmass/tolerances.h) meets it marginally, and the
// class is said to be marginal with the criterion named. A figure the
// visit lacks (Q or RMR with open lines on the form) leaves the criterion
// unknown: no class is proposed from it, and the missing lines are named.
// The classes are listed from the lightest support to the heaviest; when a
// visit meets two (marginally, on a shared range end) the heavier is
// proposed and the other named.
#include <optional>
#include <string>
#include <vector>

#include "core/tunnel/support_ranges.h"

namespace rockface::analysis {

// The ranges a class's figures are taken in (besides the bolts' ranges of
// core/tunnel/support_ranges.h), by the classes file and by a decision's
// changes alike: a round longer than 10 m is no drill-and-blast round;
// shotcrete up to half a metre (a cast lining is not shotcrete); its shear
// strength core/tunnel's, as the wedges take it (0.1-10 MPa).
inline constexpr tunnel::SupportRange kRoundLengthRange{0.1, 10.0, "m"};
inline constexpr tunnel::SupportRange kShotcreteThicknessRange{0.0, 0.5, "m"};
using tunnel::kShotcreteShearRange;

// A range of a figure: [min, max), either end open when absent.
struct FigureRange {
  std::optional<double> min, max;
};

struct BoltPattern {
  double length_m = 0;
  double spacing_m = 0;                // square pattern
  double capacity_n = 0;               // per bolt
  std::optional<double> bond_n_per_m;  // pull-out per metre of anchorage
};

struct FaceSupport {
  std::optional<BoltPattern> bolts;  // face bolts (along the drive)
  double shotcrete_m = 0;            // sealing of the face
  std::string words;                 // "sealing 5 cm, 9 GRP bolts 12 m"
};

// The face's behaviour in rockface's figures: "stable" when no wedge around
// the excavation and no block of the face fails without support (FoS >= 1
// or no mode), "structural" when one does (structurally controlled failure).
inline constexpr const char* kBehaviourStable = "stable";
inline constexpr const char* kBehaviourStructural = "structural";

struct SupportCriteria {
  std::optional<FigureRange> rmr, q;
  std::vector<std::string> behaviour;         // any of these; empty: any
  std::optional<double> max_wedge_volume_m3;  // the largest removable wedge
  std::optional<double> max_wedge_apex_m;     // its apex height
};

struct SupportClass {
  std::string name;  // "SC3"
  std::string description;
  double round_length_m = 0;
  std::optional<BoltPattern> bolts;  // roof and walls
  double shotcrete_m = 0;
  std::optional<double> shotcrete_shear_pa;  // needed to count the lining
  std::string mesh, steel_sets;              // in the designer's words; "" none
  FaceSupport face;
  std::optional<double> target_fos;  // none: kDefaultTargetFos
  SupportCriteria criteria;
};

inline constexpr double kDefaultTargetFos = 1.5;
double target_fos(const SupportClass& c);

// The support classes of one tunnel.
struct SupportClasses {
  std::string tunnel;                 // the designer's name of the tunnel / drive
  std::string source;                 // the file they were read from
  std::vector<SupportClass> classes;  // lightest first
};

// What a visit gives the match.
struct VisitFigures {
  std::optional<double> rmr;
  std::vector<std::string> rmr_missing;  // the form's open lines
  std::optional<double> q;
  std::vector<std::string> q_missing;
  std::optional<std::string> behaviour;  // kBehaviour*; none: no wedges or blocks known
  std::optional<double> largest_wedge_volume_m3, largest_wedge_apex_m;
  bool wedges_known = false;  // a wedge analysis ran (none found counts as known)
};

enum class CriterionStatus { met, marginal, not_met, unknown };
const char* words(CriterionStatus s);  // "met", "marginal", "not met", "unknown"

struct CriterionCheck {
  std::string criterion;  // "RMR", "Q", "behaviour", "wedge volume", "wedge apex"
  CriterionStatus status = CriterionStatus::unknown;
  std::string words;  // "RMR 52 in [41, 61)", "Q open: Jr, Ja not entered"
};

struct ClassMatch {
  std::string name;
  std::vector<CriterionCheck> checks;
  CriterionStatus status = CriterionStatus::unknown;  // the worst of its checks
};

struct ClassProposal {
  std::vector<ClassMatch> matches;      // one per class, in the classes' order
  std::optional<std::string> proposed;  // the class proposed, none when none is met
  bool marginal = false;                // proposed on a marginal criterion
  std::vector<std::string> notes;       // why none, which criterion is marginal / unknown
};

ClassProposal match_support_classes(const SupportClasses& classes, const VisitFigures& visit);

// The class by name; nullptr when there is none.
const SupportClass* find_class(const SupportClasses& classes, const std::string& name);

}  // namespace rockface::analysis
