#pragma once
// Named tolerances of rotational kinematics (corner, edge and remote-axis
// rotation). Each value says what error it absorbs. Lengths are relative to
// the block's size so that the same block gives the same answer from 1 mm to
// 100 m.

namespace rockface::kinematics {

// A corner C whose lever arm C - R makes an angle (sine) below this with the
// block-side normal n of a joint through C has no limit plane: its
// first-order displacement u x (C - R) is tangent to the joint for every
// axis u, and the second-order term lifts it off the joint (see
// rotation_space.h), so the constraint is void. Below 1e-9 the direction of
// n x (R - C) is set by rounding of the vertices (~1e-15 of the block size,
// amplified by short lever arms), not by the geometry.
inline constexpr double kVoidLimitPlaneSin = 1e-9;

// A corner closer than this (x block size) to the static point or to the
// rotation axis does not move at all: it gives no constraint. Matches the
// vertex merge distance of core/blocks (1e-9 x size), below which two
// corners are one.
inline constexpr double kOnAxisRel = 1e-9;

// Two joint planes whose normals make an angle (sine) below this are
// parallel for sliding rotation: rotating about the normal of one keeps the
// block in sliding contact with the other too.
inline constexpr double kParallelJointsSin = 1e-9;

// Remote-axis search: a start "hits" when the largest violation angle left
// at any corner is below this. The local minimiser reaches exactly zero when
// the feasible axes have an interior; feasible axes with sliding contact
// (slumping, rotation with a face kept tangent) are reached only as a limit,
// where Levenberg-Marquardt stops with violations from 1e-21 up to 2e-7 rad
// (measured: 400 single starts on the lined-block slumping test, lining just
// below its critical length), while starts that fail stop at 1e-5 rad or,
// almost all, above 0.7 rad. 1e-6 rad is a penetration of 1 um per metre of
// lever arm per radian of rotation: far below what any joint orientation
// can tell.
inline constexpr double kRemoteAxisHitRad = 1e-6;

// Remote-axis starts: axis points are drawn uniformly in a disc of this
// radius (x the block's bounding radius about its centroid) perpendicular to
// the axis direction: axes through the block, grazing it and passing close
// outside it. The minimiser moves the axis anywhere from there.
inline constexpr double kRemoteAxisStartRadius = 2.0;

// Early stop of the remote-axis search (RemoteAxisOptions::early_stop). The
// verdict "an axis exists" is settled by the first hit (a hit is an axis
// checked to kRemoteAxisHitRad); what more starts add is the hit rate (how
// easily the axis is found) and maybe an axis with more clearance. So once
// an axis is found and at least kRemoteAxisMinStarts starts have run, the
// search stops when the hit rate is known to +-kRemoteAxisHitRateError at
// 95 % (the half-width of the Wilson score interval of hits / starts). A
// search without a hit never stops early: "no axis" rests on every start,
// as before.
inline constexpr int kRemoteAxisMinStarts = 8;
inline constexpr double kRemoteAxisHitRateError = 0.15;

}  // namespace rockface::kinematics
