#pragma once
// Planar pieces of a boundary ref (internal to remesh/): a ref whose listed faces lie on several
// planes joined only at sharp edges — a box's faces in one "wall" physical group, as gmsh users
// write it, or an L-shaped interface — is remeshed as that many planar patches, each with a ref
// of its own for the time of the adaptation, so that their common lines are ridges (exact lines
// where two planes meet) and a planar interface meeting them has a rim that can move along its
// line. Taken for one curved patch, such a ref kept every interface meeting it as given (its rim
// vertices were on a curved patch and an interface at once).
#include <cstdint>
#include <map>

#include "remesh/tet_mesh.hpp"

namespace riemesh {

/// Gives each planar piece of a split ref but the first (pieces in the order of their first
/// face slot) a fresh ref above every face ref of m, and returns piece ref -> given ref. A ref is
/// split when its faces form two or more pieces (faces joined across edges where they are
/// coplanar within kPlaneNormal), every edge between two of its pieces turns by more than
/// angle_deg (outer faces: the angle of their outward normals; interfaces: of their planes), and
/// every piece is planar (plane_fit.hpp, `diagonal` the mesh's). Smooth curved refs (a faceted
/// cylinder turns by a few degrees from facet to facet) and refs of one plane are left alone.
std::map<std::int32_t, std::int32_t> split_planar_pieces(TetMesh& m, double angle_deg,
                                                         double diagonal);

/// Gives the faces of each piece ref of `pieces` (split_planar_pieces) their given ref again.
void restore_piece_refs(TetMesh& m, const std::map<std::int32_t, std::int32_t>& pieces);

}  // namespace riemesh
