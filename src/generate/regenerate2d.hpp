#pragma once
// Uniform refinement of a planar mesh by meshing its domain afresh (issue #4's uniform --hsiz
// case). When the metric is the same at every vertex and asks for many times the mesh's
// triangles, adapt2d would spend its passes splitting edges one by one; the unit mesh of a
// constant metric is known instead — its unit lattice (lattice2d.hpp). So the mesh's boundary and
// interface curves (with their refs, tags and corners) become a domain for mesh_domain2d, which
// cuts them to the metric on their smooth reconstruction, fills the inside with the lattice and
// lets adapt2d join the two; each region then takes back the triangle ref of the input there.
#include <span>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {

/// The domain is meshed afresh when the constant metric asks for at least this many times the
/// input's triangles (its edges about twice as long as unit, or longer).
inline constexpr double kRegenerateRatio = 4.0;

/// Whether adapt_or_regenerate2d meshes `input` afresh: a planar triangle mesh, one metric per
/// vertex, all equal (exactly), at least kRegenerateRatio times its triangles asked, every operator
/// allowed (insertion, swaps, moves), every feature curve closed (no dangling listed edge) with a
/// triangle on at least one side, no two of their vertices at one place (a crack's lips), no
/// required triangle and no required vertex off the curves. Errors in the input are left to
/// adapt2d (false).
bool regeneration_applies(const Mesh& input, std::span<const SymMat2> metrics,
                          const Adapt2dOptions& options);

/// adapt2d(input, metrics, options, on_pass), or, when regeneration_applies, the domain meshed
/// afresh (see the file comment): the same outputs (mesh with refs, tags, corners and edges;
/// metric per vertex; passes; a note saying the domain was meshed afresh), the same errors for
/// bad input (curves that do not make a domain, as in a folded mesh: adapt2d). Deterministic.
Adapt2dResult adapt_or_regenerate2d(const Mesh& input, std::span<const SymMat2> metrics,
                                    const Adapt2dOptions& options,
                                    const PassCallback& on_pass = {});

}  // namespace riemesh
