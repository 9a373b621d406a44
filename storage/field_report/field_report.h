#pragma once
// The field report of one visit: what a geologist prints or sends before the
// next excavation round, gathered from the project file. Values only; the
// pictures and the PDF are made from this (field_report_pictures.h,
// field_report_pdf.h). Every number printed comes from here, formatted by
// the functions below, so a test can compare the PDF's text with the store.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/analysis/report.h"
#include "core/photogrammetry/camera/camera_model.h"
#include "core/rockmass/rock_mass_figures.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::storage {

struct ReportedJoint {
  std::string label, set_label, source;
  double dip_deg = 0, dipdir_deg = 0;
  std::optional<double> friction_deg, cohesion_pa;
};

// A plane of the mapped face (an outline's first flat piece) or a free face
// of the excavation, for the stereonet's face circles and kinematic check.
struct ReportedFacePlane {
  std::string label;
  double dip_deg = 0, dipdir_deg = 0;
  double area_m2 = 0;  // of its outline on the 3D image
  // Whether the dip direction is the stored one (a fitted or measured
  // plane); false when taken from the outline's corners, whose winding does
  // not say which side of a steep face is the rock.
  bool oriented = true;
};

struct ReportedJointSet {
  std::string label;
  int count = 0;
  double dip_deg = 0, dipdir_deg = 0;
  double fisher_k = 0;                // +inf when every pole coincides
  std::optional<double> alpha95_deg;  // absent when undefined (fewer than two poles)
  std::string origin;                 // "stored" | "clustered from the joints"
};

// One 3D image of the visit and how it was registered to the face.
struct ReportedImage {
  std::string name, role;  // "master" | "registered"
  std::string reference;
  int tie_points = 0;
  double overlap = 0, surface_rms_m = 0, scale = 1;
};

struct ReportedControlPoint {
  std::string id;
  double residual_m = 0;
};

struct ReportedAccuracy {
  // Where the 3D image came from when rockface did not reconstruct it
  // (`rockface import`): file, format, points, frame; empty for its own.
  std::string imported_from;
  std::string scale_source, vertical_source, north_source;
  // Absent when the visit has no reconstruction of its own (a visit made by
  // `rockface measure` on another visit's 3D image) or its record does not
  // state them: said "not known", never shown as zeros (issue 41).
  std::optional<double> scale;
  std::optional<double> range_pole_m, compass_azimuth_deg, declination_deg, north_rotation_deg;
  std::optional<double> sigma_z_m, distance_m, point_spacing_m, reprojection_rms_px;
  std::optional<int> tie_points;
  std::optional<double> control_rms_m;
  std::vector<ReportedControlPoint> control_points;
  std::vector<ReportedImage> images;  // several 3D images; empty for one pair
  std::vector<std::string> warnings;
};

// The visit in the tunnel (issue 22): filled by the application (the
// profile is a computation on the visit's 3D image), absent without a tunnel.
struct ReportedTunnelPlane {
  std::string label;  // a joint or a set
  double dip_deg = 0, dipdir_deg = 0;
  std::optional<double> chainage, offset_m;  // of its point, when it has one
  std::string strike_class;                  // Bieniawski's words
  int rmr_adjustment = 0;
  double margin_deg = 0;
  bool marginal = false;
};

struct ReportedTunnelBlock {
  std::string label;
  Eigen::Vector3d survey = Eigen::Vector3d::Zero();  // centroid, survey coordinates
  double chainage = 0, offset_m = 0, height_m = 0;
};

struct ReportedTunnel {
  std::string name, drive, profile_name;
  double first_chainage = 0, last_chainage = 0;
  double perimeter_m = 0, area_m2 = 0, underbreak_tolerance_m = 0;
  std::optional<VisitPlacement> placement;
  std::vector<std::string> profile_lines;  // the round against the design, in words (not its place)
  cv::Mat developed_view;                  // BGR; empty when not placed
  std::vector<ReportedTunnelPlane> planes;
  std::vector<ReportedTunnelBlock> blocks;
};

// The wedges around the excavation (issue 23): filled by the application
// (an analysis of the tunnel's profile and the visit's sets), absent when
// the project has no tunnel or the visit fewer than three sets.
struct ReportedWedges {
  std::vector<std::string> lines;              // the input in words: section, axis, sets, support
  std::vector<std::vector<std::string>> rows;  // one per wedge, in words and units
  std::vector<std::string> notes;              // corners crossed, pyramids with no wedge, ...
  cv::Mat picture;                             // BGR: the section and the largest wedges
};

// Facets and joint sets proposed on the visit's 3D image (issue 25): filled
// by the application (firmware-app/propose) when the report is written by
// `rockface propose --report`; absent otherwise.
struct ReportedFacets {
  std::vector<std::string> lines;              // knobs, counts, areas in words
  std::vector<std::vector<std::string>> rows;  // one per set: label, orientation, K, ...
  std::vector<std::string> notes;              // clusters that are not sets, and why
  cv::Mat picture;                             // BGR: facets by set over the photograph
};

// The support of this round (issue 44): filled by the application
// (firmware-app/support) when the project holds support classes for the
// tunnel or a decision for the visit; absent otherwise.
struct ReportedSupport {
  std::vector<std::string> proposals;          // the Q chart's, Bieniawski's, the classes'
  std::vector<std::string> checks;             // per class checked, and what would fix it
  std::vector<std::vector<std::string>> rows;  // the chosen class on each wedge and block
  std::string rows_pattern;  // whose rows: "SC2", "SC2 as changed" (the decision's changes)
  std::vector<std::string> decision;  // the class chosen, changes, who, when
  cv::Mat chart;                      // BGR: the Q chart with the visit's point
};

struct FieldReport {
  std::string project_name, project_file;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  RecordId visit_id = 0;
  std::string visit_started_at, visit_source;
  // Who mapped the visit (storage/project/visit_geologist.h); none: not
  // recorded.
  std::optional<std::string> visit_geologist;

  // Camera and preset.
  std::string camera_body, lens, calibration_method;
  photogrammetry::CameraIntrinsics intrinsics;
  bool calibration_known = false;  // the first pair's calibration was read into `intrinsics`
  std::string preset;

  // The face: the first pair's left photograph and the registration of its
  // model (model = left camera frame; x_project = s R x_model + t).
  cv::Mat photograph;  // BGR; empty when the visit has no capture
  double model_scale = 1;
  Eigen::Matrix3d model_rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d model_translation = Eigen::Vector3d::Zero();
  // The traces, pieces stored from different pairs joined into one (label
  // "T1+T4", points ordered along it): label, points.
  std::vector<std::pair<std::string, std::vector<Eigen::Vector3d>>> traces;
  // Per trace, the index of its set in `sets` (-1: none): the set of the
  // joint the geologist assigned it to (its first piece's), else, when the
  // sets are clustered from the planes measured on the face, the cluster of
  // its own plane. What the browser's 3D face colours each trace by.
  std::vector<int> trace_sets;
  // How the stored traces came (issue 25): tapped by hand, proposals
  // accepted as found, proposals corrected by least-cost tracing.
  int traces_by_hand = 0, traces_proposed = 0, traces_corrected = 0;
  // Issue 27: each face outline in words, its flat pieces, how far apart
  // and their RMS ("face outline F1: 2 flat pieces, 12.0° apart, RMS 6 mm /
  // 7 mm"); those of one flat piece told in one line (issue 39;
  // storage/scene/face_outline_words.h face_outline_summary).
  std::vector<std::string> face_outlines;
  std::vector<ReportedFacePlane> face_planes;  // in the order measured

  ReportedAccuracy accuracy;
  std::vector<ReportedJoint> joints;
  std::vector<ReportedJointSet> sets;
  // The poles on the stereonet: of the planes measured on the face when two
  // or more were (a joined trace once, the mean of its pieces' planes), else
  // of the joints (in their order).
  std::vector<Eigen::Vector3d> poles;
  std::vector<int> pole_sets;  // per pole: index into `sets`, or -1

  std::optional<RecordId> analysis_id;
  std::vector<std::string> effects;
  // The verdicts as stored (points absolute, as in the report; subtract
  // `datum` for the project frame).
  std::vector<analysis::ReportBlock> blocks;

  std::optional<ReportedTunnel> tunnel;
  std::optional<ReportedWedges> wedges;

  // The rock mass in figures and its classifications (issue 23): filled by
  // the application (firmware-app/rockmass), absent with the reason in
  // rockmass_note when the visit has no traces.
  std::optional<rockmass::RockMassFigures> rockmass;
  std::string rockmass_note;

  std::optional<ReportedFacets> facets;    // issue 25's proposals
  std::optional<ReportedSupport> support;  // issue 44's round support
};

// Reads everything the report shows for `visit_id` (InputError naming the
// visit when the project has no such visit).
FieldReport collect_field_report(ProjectStore& store, RecordId visit_id);

// How numbers are printed (fixed decimals; "-" for none).
std::string report_number(double value, int decimals);
std::string report_number(const std::optional<double>& value, int decimals);
// A block's verdict in words: "removable", "finite, keyed", "infinite"; "?" appended when marginal.
std::string report_verdict(const analysis::ReportBlock& block);
// "sliding on J1+J2", "falling", "none".
std::string report_mode(const analysis::ReportBlock& block);
// "2/8 corners, 1/12 edges" (+ "; remote axis" / "; no remote axis"), "-" when not analysed.
std::string report_rotation(const analysis::ReportBlock& block);

}  // namespace rockface::storage
