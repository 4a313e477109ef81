// Medit binary .meshb (libMeshb file versions 1 to 4): reader and writer.
#include <algorithm>

#include "io/atomic_file.hpp"
#include "io/medit_detail.hpp"
#include "io/meshb_stream.hpp"

namespace riemesh::medit_detail {

namespace {

constexpr std::array<Bound, 4> kAllVertices{Bound::kVertex, Bound::kVertex, Bound::kVertex,
                                            Bound::kVertex};

Locator binary_locator(const std::string& path, std::size_t data_pos, std::size_t entry_bytes,
                       std::size_t int_size) {
  return [=](std::size_t entry, int column) {
    return path + ": byte " +
           std::to_string(data_pos + entry * entry_bytes +
                          static_cast<std::size_t>(column) * int_size);
  };
}

class BinaryMeshReader {
 public:
  BinaryMeshReader(const std::string& path, std::string_view bytes)
      : path_(path), in_(path, bytes) {}

  Mesh read(const MeditReadOptions& options) {
    Mesh& m = out_.mesh;
    int code = 0;
    while (in_.next_keyword(code)) {
      bool read = true;
      switch (code) {
        case kVertices:
          vertices();
          break;
        case kEdges:
          elements(2, m.edges, m.edge_ref);
          break;
        case kTriangles:
          elements(3, m.triangles, m.tri_ref);
          break;
        case kTetrahedra:
          if (in_.require_dim() != 3) in_.fail_at(in_.offset(), "tetrahedra in a 2D mesh");
          elements(4, m.tets, m.tet_ref);
          break;
        case kCorners:
        case kRidges:
        case kRequiredVertices:
        case kRequiredEdges:
        case kRequiredTriangles:
          id_list();
          break;
        case kNormals:
          vectors(m.normals);
          break;
        case kTangents:
          vectors(m.tangents);
          break;
        case kNormalAtVertices:
          pairs(m.normal_at_vertex, Bound::kNormal);
          break;
        case kTangentAtVertices:
          pairs(m.tangent_at_vertex, Bound::kTangent);
          break;
        default:
          refuse_elements(code);
          read = false;
          break;
      }
      in_.end_keyword(read);
    }
    if (in_.dim() == 0) fail(path_, "Dimension", "missing");
    m.dim = in_.dim();
    return out_.finish(options);
  }

 private:
  std::size_t isize() const { return static_cast<std::size_t>(in_.int_size()); }

  /// Quadrilaterals, Prisms, P2 elements ...: refused when the section holds any (see the ASCII
  /// reader), skipped when empty.
  void refuse_elements(int code) {
    int ints = 0;
    const char* name = skipped_keyword(code, ints);
    if (!name || !holds_elements(name)) return;
    const std::size_t at = in_.offset();
    const std::size_t n = in_.count(static_cast<std::size_t>(ints) * isize());
    if (n > 0) fail(in_.where(at), name, unread_elements(n));
  }

  void vertices() {
    Mesh& m = out_.mesh;
    const int dim = in_.require_dim();
    const std::size_t n = in_.count(dim * in_.real_size() + isize());
    m.coords.reserve(m.coords.size() + n * dim);
    m.vert_ref.reserve(m.vert_ref.size() + n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < dim; ++k) m.coords.push_back(in_.real());
      m.vert_ref.push_back(in_.ref());
    }
  }

  void elements(int nodes, std::vector<Id>& ids, std::vector<std::int32_t>& refs) {
    const std::size_t entry_bytes = (nodes + 1) * isize();
    const std::size_t n = in_.count(entry_bytes);
    const std::size_t begin = ids.size();
    const Locator locate = binary_locator(path_, in_.offset(), entry_bytes, isize());
    ids.reserve(begin + n * nodes);
    refs.reserve(refs.size() + n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < nodes; ++k) ids.push_back(in_.id());
      refs.push_back(in_.ref());
    }
    out_.add_block(current_code(), ids, begin, nodes, kAllVertices, locate);
  }

  void id_list() {
    static constexpr Bound kBound[] = {Bound::kVertex, Bound::kEdge, Bound::kVertex, Bound::kEdge,
                                       Bound::kTriangle};
    const int code = current_code();
    std::vector<Id>& ids = out_.tag_list(code);
    const std::size_t n = in_.count(isize());
    const std::size_t begin = ids.size();
    const Locator locate = binary_locator(path_, in_.offset(), isize(), isize());
    for (std::size_t i = 0; i < n; ++i) ids.push_back(in_.id());
    out_.add_block(code, ids, begin, 1, {kBound[code - kCorners]}, locate);
  }

  void vectors(std::vector<double>& values) {
    const int dim = in_.require_dim();
    const std::size_t n = in_.count(dim * in_.real_size());
    values.reserve(values.size() + 3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < dim; ++k) values.push_back(in_.real());
      if (dim == 2) values.push_back(0.0);
    }
  }

  void pairs(std::vector<Id>& ids, Bound second) {
    const std::size_t n = in_.count(2 * isize());
    const std::size_t begin = ids.size();
    const Locator locate = binary_locator(path_, in_.offset(), 2 * isize(), isize());
    for (std::size_t i = 0; i < 2 * n; ++i) ids.push_back(in_.id());
    out_.add_block(current_code(), ids, begin, 2, {Bound::kVertex, second}, locate);
  }

  int current_code() const { return in_.code(); }

  std::string path_;
  MeshbReader in_;
  MeshAssembler out_;
};

void write_elements(MeshbWriter& out, int code, const std::vector<Id>& ids,
                    const std::vector<std::int32_t>& refs, int nodes) {
  if (ids.empty()) return;
  const std::size_t n = ids.size() / nodes;
  out.keyword(code, static_cast<std::int64_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < nodes; ++k) out.integer(std::int64_t{ids[i * nodes + k]} + 1);
    out.integer(ref_at(refs, i));
  }
}

void write_ids(MeshbWriter& out, int code, const std::vector<Id>& ids) {
  if (ids.empty()) return;
  out.keyword(code, static_cast<std::int64_t>(ids.size()));
  for (Id id : ids) out.integer(std::int64_t{id} + 1);
}

void write_vectors(MeshbWriter& out, int code, const std::vector<double>& values, int dim) {
  if (values.empty()) return;
  const std::size_t n = values.size() / 3;
  out.keyword(code, static_cast<std::int64_t>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) out.real(values[3 * i + k]);
}

// NormalAtVertices, TangentAtVertices: (vertex, normal or tangent) pairs.
void write_pairs(MeshbWriter& out, int code, const std::vector<Id>& ids) {
  if (ids.empty()) return;
  out.keyword(code, static_cast<std::int64_t>(ids.size() / 2));
  for (Id id : ids) out.integer(std::int64_t{id} + 1);
}

}  // namespace

Mesh read_medit_binary(const std::string& path, std::string_view bytes,
                       const MeditReadOptions& options) {
  return BinaryMeshReader(path, bytes).read(options);
}

void write_medit_binary(const Mesh& mesh, AtomicFile& file, const MeditWriteOptions& options) {
  const int dim = mesh.dim;
  const std::uint64_t nv = mesh.num_vertices();
  const std::uint64_t estimate =
      64 * 16 + nv * (8 * dim + 8) +
      8 * (mesh.edges.size() + mesh.triangles.size() + mesh.tets.size() +
           mesh.normal_at_vertex.size() + mesh.tangent_at_vertex.size() + mesh.normals.size() +
           mesh.tangents.size()) +
      8 * (mesh.num_edges() + mesh.num_triangles() + mesh.num_tets() + nv);
  const std::uint64_t max_count =
      std::max({nv, std::uint64_t{mesh.num_edges()}, std::uint64_t{mesh.num_triangles()},
                std::uint64_t{mesh.num_tets()}});
  const int version =
      choose_meshb_version(options.binary_version, estimate, max_count, file.path());
  MeshbWriter out(version, dim, estimate);
  if (nv > 0) {
    out.keyword(kVertices, static_cast<std::int64_t>(nv));
    for (std::size_t v = 0; v < nv; ++v) {
      for (int k = 0; k < dim; ++k) out.real(mesh.coords[v * dim + k]);
      out.integer(ref_at(mesh.vert_ref, v));
    }
  }
  write_elements(out, kEdges, mesh.edges, mesh.edge_ref, 2);
  write_elements(out, kTriangles, output_triangles(mesh, options.ccw_2d), mesh.tri_ref, 3);
  write_elements(out, kTetrahedra, mesh.tets, mesh.tet_ref, 4);
  write_ids(out, kCorners, tagged(mesh.vert_tag, kTagCorner));
  write_ids(out, kRequiredVertices, tagged(mesh.vert_tag, kTagRequired));
  write_ids(out, kRidges, tagged(mesh.edge_tag, kTagRidge));
  write_ids(out, kRequiredEdges, tagged(mesh.edge_tag, kTagRequired));
  write_ids(out, kRequiredTriangles, tagged(mesh.tri_tag, kTagRequired));
  write_vectors(out, kNormals, mesh.normals, dim);
  write_pairs(out, kNormalAtVertices, mesh.normal_at_vertex);
  write_vectors(out, kTangents, mesh.tangents, dim);
  write_pairs(out, kTangentAtVertices, mesh.tangent_at_vertex);
  file.write(out.finish());
}

}  // namespace riemesh::medit_detail
