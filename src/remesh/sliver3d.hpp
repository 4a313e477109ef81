#pragma once
// Sliver removal for the 3D remesher (internal to remesh/): the final optimisation of every
// pass, aimed at the tets below a quality target, with bounded sweeps.
#include "remesh/adapt2d.hpp"
#include "remesh/edges3d.hpp"
#include "remesh/remesh3d_context.hpp"

namespace riemesh {

struct SliverLimits {
  double target = 0.55;      ///< tets below this quality are worked on
  double max_length = 1.6;   ///< no swap or collapse creates a longer edge (metric)
  int sweeps = 4;            ///< at most this many sweeps over the bad tets
  double budget = 0.02;      ///< each sweep works on the worst tets only, this fraction of all
  bool swap = true, move = true, collapse = true;  ///< the operators allowed
  /// A new interior vertex for the slivers none of whose vertices may move (star_sliver, else
  /// split_sliver): with a kept surface.
  bool split_fixed = false;
};

/// Moves v (in its plane or on its line when on the boundary) to raise the worst quality of its
/// ball: candidates are the weighted mean of the ideal apexes over the faces opposite v (the
/// point making each ball tet regular in its metric, weights growing as the tets get worse),
/// the ideal apex of the worst tet, and those moves at half and a quarter. kApplied when the
/// ball's worst quality went up.
Outcome optimise_vertex(Remesh3dContext& ctx, Id v);

/// Refines a position p of vertex v (its ball's worst quality `best` there, ball: v's tets) by a
/// compass search along the principal directions of v's metric: steps of 0.2 metric units halved
/// down to 0.025, moving to the best of the six neighbours while that raises the worst quality
/// (v's metric and the mesh unchanged) and no edge at v leaves the band [1/sqrt 2, sqrt 2] or
/// gets further out of it (at most 12 moves). Boundary vertices stay on their plane, line or
/// curve (Remesh3dContext::constrain). Returns the worst quality at the final p; the mesh is not
/// changed. optimise_vertex refines its best candidate so when the ball is below 0.5 and v is
/// interior (on the bunny's curved boundary the boundary moves lowered the worst tet: README).
double compass_search(Remesh3dContext& ctx, Id v, const std::vector<Id>& ball, Vec3& p,
                      double best);

/// Cuts tet t by a new interior vertex off one of its interior edges (no listed face on it):
/// every tet of that edge's shell is cut in two, as split_edge, at the point found for each
/// interior edge of t (from the middle, moves toward the ideal apexes of the new tets) that
/// gives the best worst new tet; kApplied when that is above t's quality + min_gain. For the
/// slivers whose four vertices are on a kept surface, which no other operator removes. The
/// surface is unchanged.
Outcome split_sliver(Remesh3dContext& ctx, Id t, double min_gain, Id* created);

/// Replaces tet t and the tets around it by the star of a new interior vertex: its position
/// on either side of one of t's faces (the ideal apex, or 1/2, 1/4, 0.12, 0.06, 0.03 of the way
/// there from the face's centroid), the cavity grown from t across the unlisted faces that the
/// vertex does not see with a tet above `floor` (at most 64 tets, every cavity vertex left on
/// its boundary). The candidate giving the best worst tet (above floor) wins. For the flat tets
/// that cover a kept surface (four surface vertices), which no other operator removes; the
/// surface is unchanged.
Outcome star_sliver(Remesh3dContext& ctx, Id t, double floor, Id* created);

/// For each tet below limits.target, worst first (at most max(100, budget × tets) of them:
/// far from adapted, most tets are bad and the sweeps of the pass deal with them): edge swaps of its 6 edges, face swaps of its
/// 4 faces, optimisation of its 4 vertices, collapses of its edges (shortest first) that do not
/// lower the ball's worst quality; with limits.split_fixed, for a tet below quality 0.1 none of
/// whose vertices may move, star_sliver or else split_sliver (the new vertex then optimised,
/// counted in st.splits). Repeated while something changed, at most limits.sweeps
/// times. Returns the number of operations applied (swaps, moves and collapses added to st).
/// With nbrs and memo (and without split_fixed, whose cavities reach beyond the balls): the tets
/// on which an attempt failed with their vertices' balls unchanged since are skipped (memo).
long sliver_sweeps(Remesh3dContext& ctx, const SliverLimits& limits, PassStats& st,
                   const NeighbourTable* nbrs = nullptr, FailureMemo* memo = nullptr);

/// The failure memos of the 3D sweeps, kept by the driver across its passes.
struct SweepMemos {
  FailureMemo swaps, slivers;
};

}  // namespace riemesh
