// The faces light crosses when a light propagation volume propagates one step, and the solid angle
// each subtends from the source cell's centre [Martin 2012, §3.2.3, §4.2, App. A]. Computed once
// in double from the closed form for a rectangle; the thesis's two-triangle method checks it
// (tests/lpv/propagation_faces_test.cpp).
//
// Cells are unit cubes, the source centre at the origin. For a destination cell at offset o, a
// face entry is one face of the destination that light from the source enters through:
// - 6 directions (LPV, Kaplanyan & Dachsbacher): o = +-e_a, five faces each (the far face and the
//   four side faces not shared with the source), 30 entries;
// - 26 directions (HOLPV, Martin): every o in {-1,0,1}^3 \ 0, the faces of the destination on the
//   outside of the 3x3x3 block (one, two or three), 54 entries.
// The solid angles of each table sum to 4 pi.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace voxgi::lpv {

struct PropagationFace {
  glm::ivec3 offset;      // destination cell - source cell
  glm::dvec3 centre;      // the face's centre, relative to the source centre
  glm::dvec3 direction;   // unit vector from the source centre to the face centre (omega_f)
  glm::dvec3 normal;      // the face's outward axis normal (n_f): the lobe it is re-emitted as
  double solidAngle = 0;  // Omega_f, from the source centre
};

// The 30 (directions = 6) or 54 (directions = 26) face entries, in a fixed order: offsets in
// z-major, y, x order from -1 to 1, faces by axis x, y, z.
std::vector<PropagationFace> propagationFaces(int directions);

// Solid angle of the rectangle [x0, x1] x [y0, y1] in the plane at distance d > 0 along the third
// axis, seen from the origin: F(x1,y1) - F(x0,y1) - F(x1,y0) + F(x0,y0) with
// F(x, y) = atan(x y / (d sqrt(x^2 + y^2 + d^2))).
double rectangleSolidAngle(double x0, double x1, double y0, double y1, double d);

// Solid angle of the triangle (a, b, c) seen from the origin [Van Oosterom & Strackee 1983], as
// 2 atan2(|a . (b x c)|, |a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|): the thesis's Appendix A uses
// atan, which is wrong for a triangle wider than a hemisphere.
double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

}  // namespace voxgi::lpv
