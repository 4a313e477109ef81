#pragma once
// Statistics of a mesh that need no metric: entity counts, references, element measures, and the
// two small accumulators (running min/max/mean, fixed-bin histogram) that the metric statistics
// (metric/mesh_quality.hpp) and the CLI reports share. Pure functions: no printing.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

/// Running minimum, maximum, sum and mean of a sequence of values (NaN-free input assumed).
struct Summary {
  std::size_t count = 0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;

  void add(double v);
  double mean() const { return count ? sum / static_cast<double>(count) : 0.0; }
};

/// Summary of all values.
Summary summarize(std::span<const double> values);

/// Counts of values in bins [edges[i], edges[i+1]) (the last bin closed); values below edges[0]
/// fall in the first bin and values above edges.back() in the last, so counts sum to the total.
struct Histogram {
  std::vector<double> edges;        // bins + 1 increasing values
  std::vector<std::size_t> counts;  // one per bin
  std::size_t total() const;
};

/// An empty histogram on the given bin edges (at least two, increasing; else InputError).
Histogram make_histogram(std::vector<double> edges);
/// `bins` equal bins on [lo, hi].
Histogram uniform_histogram(double lo, double hi, int bins);
/// Adds value v (clamped to the end bins as described above).
void add(Histogram& h, double v);
/// A histogram of all values on the given bin edges.
Histogram histogram(std::vector<double> edges, std::span<const double> values);

/// Entity counts of a mesh. Edges are the unique edges of the elements (tetrahedra of a volume,
/// triangles otherwise), boundary_* the entities listed in the file.
struct MeshCounts {
  std::size_t vertices = 0;
  std::size_t edges = 0;      // unique element edges
  std::size_t triangles = 0;  // elements in 2D and on surfaces; boundary faces of a volume
  std::size_t tetrahedra = 0;
  std::size_t boundary_edges = 0;      // listed Edges
  std::size_t boundary_triangles = 0;  // listed Triangles of a volume mesh (0 otherwise)
  std::size_t corners = 0;             // vertices tagged kTagCorner
  std::size_t ridges = 0;              // edges tagged kTagRidge
  std::size_t required_vertices = 0;   // vertices tagged kTagRequired
};

/// The distinct references of each entity kind, sorted.
struct MeshRefs {
  std::vector<std::int32_t> vertices, edges, triangles, tetrahedra;
};

/// Counts of `mesh`; builds the element adjacency for the edge count (InputError on bad ids).
MeshCounts count_entities(const Mesh& mesh);
MeshRefs distinct_refs(const Mesh& mesh);

/// Measure of each element: signed area (planar triangles, positive counter-clockwise), area
/// (surface triangles, unsigned) or signed volume (tetrahedra, positive when right-handed). Empty
/// for a mesh without elements. Ids must be in range (see check_mesh).
std::vector<double> element_measures(const Mesh& mesh);

/// Number of elements of the mesh's main simplex array and their vertex count (3 or 4).
std::size_t num_elements(const Mesh& mesh);
int verts_per_element(const Mesh& mesh);
/// The vertex ids of element e.
std::span<const Id> element(const Mesh& mesh, std::size_t e);

}  // namespace riemesh
