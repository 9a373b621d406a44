// The analysis input's validator (core/analysis/analysis_input_check.h) on
// values built in code, no file: each refusal names the source and the field
// path in the words the scene reader has always used for a scene file.
#include "core/analysis/analysis_input_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/support/refusal.h"

namespace {

using namespace rockface::analysis;
using rockface::test::refusal;

// A small input every check lets through: two joints, a free face, a block
// of each form, a patch, a trace on a joint, water on one joint.
AnalysisInput good_input() {
  AnalysisInput in;
  in.source = "S";
  in.joints = {{"J1", 60, 90, Eigen::Vector3d(0, 0, 0), 30.0, 0.0},
               {"J2", 60, 270, Eigen::Vector3d(1, 0, 0), std::nullopt, std::nullopt}};
  in.free_faces = {{"F1", 0, 0, Eigen::Vector3d(0, 0, 1), 1, ""}};
  SceneBlock wedge;
  wedge.id = "B1";
  wedge.halfspaces = {{"J1", 0}, {"J2", 0}, {"F1", 1}};
  SceneBlock tetra;
  tetra.id = "B2";
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.faces = {{"J1", {0, 2, 1}}, {"J2", {0, 1, 3}}, {"F1", {0, 3, 2}}, {"F1", {1, 2, 3}}};
  in.blocks = {wedge, tetra};
  in.patches = {{"S1", {{0, 0, 1}, {2, 0, 1}, {2, 2, 1}}}};
  in.traces = {{"T1", std::string("J1"), {{0, 0, 1}, {1, 1, 1}}}, {"T2", std::nullopt, {}}};
  SceneWater water;
  water.joints = {"J2"};
  in.effects.water = water;
  in.effects.joint_law = SceneJointLaw{};
  return in;
}

std::string refusal_of(const AnalysisInput& in) {
  return refusal([&] { check_analysis_input(in); });
}

TEST(AnalysisInputCheck, AGoodInputIsAccepted) {
  EXPECT_EQ(refusal_of(good_input()), "accepted");
  // A trace with fewer than two points is the trace network's to refuse.
  AnalysisInput in = good_input();
  in.traces[1].points = {{0, 0, 0}};
  EXPECT_EQ(refusal_of(in), "accepted");
}

TEST(AnalysisInputCheck, ANumberOutOfItsRangeIsQuotedAsWritten) {
  AnalysisInput in = good_input();
  in.joints[1].dip = 95;
  EXPECT_EQ(refusal_of(in), "S: joints[1].dip: 95 is outside [0, 90]");
  in = good_input();
  in.joints[0].friction = 90;  // the range is open at 90
  EXPECT_EQ(refusal_of(in), "S: joints[0].friction: 90 is outside [0, 90)");
  in = good_input();
  in.joints[0].cohesion = -0.5;
  EXPECT_EQ(refusal_of(in), "S: joints[0].cohesion: -0.5 is outside [0, 1e+08]");
  in = good_input();
  in.joints[0].cohesion = 1e308;  // issue 41: a wedge's FoS overflowed
  EXPECT_EQ(refusal_of(in), "S: joints[0].cohesion: 1e+308 is outside [0, 1e+08]");
  in = good_input();
  in.density = 0;
  EXPECT_EQ(refusal_of(in), "S: rock.density: 0 must be positive");
  in = good_input();
  in.effects.bolts.push_back({Eigen::Vector3d::Zero(), 10, 95.5, 1e6});
  EXPECT_EQ(refusal_of(in), "S: effects.bolts[0].plunge: 95.5 is outside [-90, 90]");
  in = good_input();
  in.effects.joint_law->poisson_ratio = 0.5;
  EXPECT_EQ(refusal_of(in), "S: effects.joint_law.poisson_ratio: 0.5 is outside [-0.99, 0.49]");
}

TEST(AnalysisInputCheck, ANumberThatIsNoNumberIsRefused) {
  AnalysisInput in = good_input();
  in.free_faces[0].point->y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal_of(in), "S: free_faces[0].point[1]: must be finite");
  in = good_input();
  in.gravity.z() = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal_of(in), "S: gravity[2]: must be finite");
}

TEST(AnalysisInputCheck, IdsAreUniqueAndEveryIdReferredToIsKnown) {
  AnalysisInput in = good_input();
  in.free_faces[0].id = "J2";  // planes share one name space
  EXPECT_EQ(refusal_of(in), "S: free_faces[0].id: duplicate id \"J2\"");
  in = good_input();
  in.traces[1].id = "T1";
  EXPECT_EQ(refusal_of(in), "S: traces[1].id: duplicate id \"T1\"");
  in = good_input();
  in.blocks[0].halfspaces["J9"] = 1;
  EXPECT_EQ(refusal_of(in), "S: blocks[0].halfspaces.J9: unknown plane id \"J9\"");
  in = good_input();
  in.blocks[1].faces[2].plane = "F7";
  EXPECT_EQ(refusal_of(in), "S: blocks[1].faces[2].plane: unknown plane id \"F7\"");
  in = good_input();
  in.traces[1].joint = "F1";  // a free face is no joint
  EXPECT_EQ(refusal_of(in), "S: traces[1].joint: unknown joint id \"F1\"");
  in = good_input();
  in.effects.water->joints.push_back("J3");
  EXPECT_EQ(refusal_of(in), "S: effects.water.joints[1]: unknown joint id \"J3\"");
  in = good_input();
  in.joints[1].id.clear();
  EXPECT_EQ(refusal_of(in), "S: joints[1].id: must not be empty");
}

TEST(AnalysisInputCheck, ShapesNeedTheirPointsAndVertices) {
  AnalysisInput in = good_input();
  in.patches[0].polygon.pop_back();
  EXPECT_EQ(refusal_of(in), "S: surface.patches[0].polygon: needs at least 3 points");
  in = good_input();
  in.blocks[1].faces[3].loop = {1, 2};
  EXPECT_EQ(refusal_of(in), "S: blocks[1].faces[3].loop: needs at least 3 vertices");
  in = good_input();
  in.blocks[1].faces[0].loop[1] = 4;
  EXPECT_EQ(refusal_of(in),
            "S: blocks[1].faces[0].loop[1]: vertex index 4 is out of range (block has 4 "
            "vertices)");
  in = good_input();
  in.blocks[0].vertices = in.blocks[1].vertices;  // both forms at once
  EXPECT_EQ(refusal_of(in), "S: blocks[0]: give either \"halfspaces\" or \"vertices\" + \"faces\"");
  in = good_input();
  in.blocks[0].halfspaces["F1"] = 2;
  EXPECT_EQ(refusal_of(in), "S: blocks[0].halfspaces.F1: 2 is neither \"upper\" nor \"lower\"");
}

TEST(AnalysisInputCheck, WordsAreAmongTheKnownOnes) {
  AnalysisInput in = good_input();
  in.analysis.stability = "limit";
  EXPECT_EQ(refusal_of(in),
            "S: analysis.stability: \"limit\" is not limit_equilibrium, equilibrium_path or none");
  in = good_input();
  in.effects.joint_law->model = "mohr";
  EXPECT_EQ(refusal_of(in),
            "S: effects.joint_law.model: \"mohr\" is not barton_bandis, grasselli or coulomb");
  in = good_input();
  in.effects.forces.push_back({Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::Zero(), "world"});
  EXPECT_EQ(refusal_of(in),
            "S: effects.forces[0].frame: \"world\" is neither \"space\" nor \"block\"");
  EXPECT_EQ(refusal([] { rock_side_code("up", "S: free_faces[0].rock_side"); }),
            "S: free_faces[0].rock_side: \"up\" is neither \"upper\" nor \"lower\"");
  EXPECT_EQ(rock_side_code("upper", "S"), 0);
  EXPECT_EQ(rock_side_code("lower", "S"), 1);
}

TEST(AnalysisInputCheck, TheAnalysisOptionsAndTheMotionStayInTheirBounds) {
  AnalysisInput in = good_input();
  in.analysis.remote_axis = SceneRemoteAxis{0, 1};
  EXPECT_EQ(refusal_of(in), "S: analysis.remote_axis.starts: must be between 1 and 100000");
  in = good_input();
  in.analysis.contact_density = 65;
  EXPECT_EQ(refusal_of(in),
            "S: analysis.contact_density: must be between 1 and 64 sub-divisions per edge");
  in = good_input();
  in.analysis.dynamics = SceneDynamics{};
  in.analysis.dynamics->duration_s = 600;
  in.analysis.dynamics->sample_s = 0.001;  // 600000 samples
  EXPECT_EQ(refusal_of(in),
            "S: analysis.dynamics.sample_s: more than 100000 samples over duration_s");
  in.analysis.dynamics->sample_s = 0.2;
  in.analysis.dynamics->floor = SceneFloor{Eigen::Vector3d::Zero(), 90, 0};
  EXPECT_EQ(refusal_of(in), "S: analysis.dynamics.floor.dip: 90 is outside [0, 90)");
  in = good_input();
  in.effects.insitu_stress = Eigen::Matrix3d::Identity();
  (*in.effects.insitu_stress)(0, 1) = 1e6;
  EXPECT_EQ(refusal_of(in), "S: effects.insitu_stress.tensor: must be symmetric");
}

TEST(AnalysisInputCheck, NumbersAreQuotedAsAJsonWriterWritesThem) {
  EXPECT_EQ(number_as_written(95), "95");
  EXPECT_EQ(number_as_written(-3), "-3");
  EXPECT_EQ(number_as_written(0.5), "0.5");
  EXPECT_EQ(number_as_written(95.25), "95.25");
  EXPECT_EQ(number_as_written(0.0001), "0.0001");
  EXPECT_EQ(number_as_written(1e-5), "1e-05");
  EXPECT_EQ(number_as_written(1.5e-7), "1.5e-07");
  EXPECT_EQ(number_as_written(1e20), "1e+20");
  EXPECT_EQ(number_as_written(1e15), "1e+15");  // past 15 digits: as an exponent
  EXPECT_EQ(number_as_written(-2.5e300), "-2.5e+300");
}

}  // namespace
