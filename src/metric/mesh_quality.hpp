#pragma once
// Metric-field statistics of a mesh (the field-level side of the metric layer): element quality
// and size in a per-vertex metric field (or the identity), and metric edge lengths. A metric
// field is one packed SymMat<dim> per vertex, in the .sol order (core/symmat.hpp).
//
// Element metric: the log-Euclidean mean of the element's vertex metrics (BOOK.md §1, "the metric
// at the element"); edge length: the closed form for geometric size variation along the edge,
// (l_a − l_b) / ln(l_a / l_b) (the UGAWG convention, metric/edge_length.hpp), and where the end
// metrics do not commute (the metric turns along the edge) Simpson's rule on the log-Euclidean
// field, as the remeshers measure (edge_length_simpson).
#include <cstddef>
#include <span>
#include <vector>

#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// Edges of the length histogram: 0, then 2^(k/2) for k = -4..5 (0.25 .. 5.66); the unit range
/// [1/√2, √2) is bins 4 and 5.
std::vector<double> length_histogram_edges();
/// Edges of the quality histogram: 10 equal bins on [0, 1].
std::vector<double> quality_histogram_edges();

/// Checks that `metric` holds dim(dim+1)/2 finite numbers per vertex of `mesh` forming an SPD
/// tensor. Throws InputError naming the first bad vertex (1-based, as in Medit files).
void validate_metric_field(const Mesh& mesh, std::span<const double> metric);

/// Mean-ratio quality of every element (the tetrahedra of a volume, the triangles otherwise) in
/// the log-Euclidean mean of its vertex metrics, or in the identity (Euclidean) when `metric` is
/// empty: 1 for the regular simplex, → 0 when flat; negative for inverted planar triangles and
/// tetrahedra (surface triangles have no orientation). The metric must be valid (see above).
std::vector<double> element_qualities(const Mesh& mesh, std::span<const double> metric = {});

/// Size of every element: with no metric, the edge of the regular simplex of the same
/// (unsigned) measure; with a metric, the isotropic size det(M_K)^(-1/(2 dim)) of the element's
/// mean metric M_K.
std::vector<double> element_sizes(const Mesh& mesh, std::span<const double> metric = {});

/// Length in the metric field of each unique edge of adj (adj.edges order).
std::vector<double> metric_edge_lengths(const Mesh& mesh, const Adjacency& adj,
                                        std::span<const double> metric);

/// Fraction of lengths in the unit range [1/√2, √2] (0 when there are none).
double unit_length_fraction(std::span<const double> lengths);

}  // namespace riemesh
