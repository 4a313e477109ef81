// Medit ASCII .mesh: reader and writer.
#include "core/error.hpp"
#include "io/medit_ascii_reader.hpp"
#include "io/text_out.hpp"

namespace riemesh::medit_detail {

namespace {

constexpr std::array<Bound, 4> kAllVertices{Bound::kVertex, Bound::kVertex, Bound::kVertex,
                                            Bound::kVertex};

void read_vertices(AsciiMeditReader& in, std::string_view kw, Mesh& mesh) {
  const int dim = in.require_dim(kw);
  const std::size_t n = in.count(kw, dim + 1);
  mesh.coords.reserve(mesh.coords.size() + n * dim);
  mesh.vert_ref.reserve(mesh.vert_ref.size() + n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) mesh.coords.push_back(in.real(kw));
    mesh.vert_ref.push_back(in.ref(kw));
  }
}

// Edges, Triangles, Tetrahedra: `nodes` vertex ids and a ref per entry.
void read_elements(AsciiMeditReader& in, std::string_view kw, int code, int nodes,
                   std::vector<Id>& ids, std::vector<std::int32_t>& refs, MeshAssembler& out) {
  const std::size_t n = in.count(kw, nodes + 1);
  const Locator locate = in.locator(nodes + 1);
  const std::size_t begin = ids.size();
  ids.reserve(begin + n * nodes);
  refs.reserve(refs.size() + n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < nodes; ++k) ids.push_back(in.id(kw));
    refs.push_back(in.ref(kw));
  }
  out.add_block(code, ids, begin, nodes, kAllVertices, locate);
}

// Corners, Ridges, Required*: one id per entry.
void read_id_list(AsciiMeditReader& in, std::string_view kw, int code, MeshAssembler& out) {
  static constexpr Bound kBound[] = {Bound::kVertex, Bound::kEdge, Bound::kVertex, Bound::kEdge,
                                     Bound::kTriangle};
  std::vector<Id>& ids = out.tag_list(code);
  const std::size_t n = in.count(kw, 1);
  const Locator locate = in.locator(1);
  const std::size_t begin = ids.size();
  for (std::size_t i = 0; i < n; ++i) ids.push_back(in.id(kw));
  out.add_block(code, ids, begin, 1, {kBound[code - kCorners]}, locate);
}

// Normals, Tangents: dim reals per entry, stored with 3 components.
void read_vectors(AsciiMeditReader& in, std::string_view kw, std::vector<double>& values) {
  const int dim = in.require_dim(kw);
  const std::size_t n = in.count(kw, dim);
  values.reserve(values.size() + 3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) values.push_back(in.real(kw));
    if (dim == 2) values.push_back(0.0);
  }
}

// NormalAtVertices, TangentAtVertices: (vertex, normal or tangent) pairs.
void read_pairs(AsciiMeditReader& in, std::string_view kw, int code, std::vector<Id>& ids,
                Bound second, MeshAssembler& out) {
  const std::size_t n = in.count(kw, 2);
  const Locator locate = in.locator(2);
  const std::size_t begin = ids.size();
  for (std::size_t i = 0; i < 2 * n; ++i) ids.push_back(in.id(kw));
  out.add_block(code, ids, begin, 2, {Bound::kVertex, second}, locate);
}

}  // namespace

Mesh read_medit_ascii(const std::string& path, std::string_view text,
                      const MeditReadOptions& options) {
  AsciiMeditReader in(path, text);
  in.report_unknown(options.unknown_keywords);
  MeshAssembler out;
  Mesh& m = out.mesh;
  std::string_view kw;
  int code = 0;
  while (in.next_keyword(kw, code)) {
    switch (code) {
      case kVertices:
        read_vertices(in, kw, m);
        break;
      case kEdges:
        read_elements(in, kw, code, 2, m.edges, m.edge_ref, out);
        break;
      case kTriangles:
        read_elements(in, kw, code, 3, m.triangles, m.tri_ref, out);
        break;
      case kTetrahedra:
        if (in.require_dim(kw) != 3) in.fail_here(kw, "tetrahedra in a 2D mesh");
        read_elements(in, kw, code, 4, m.tets, m.tet_ref, out);
        break;
      case kCorners:
      case kRidges:
      case kRequiredVertices:
      case kRequiredEdges:
      case kRequiredTriangles:
        read_id_list(in, kw, code, out);
        break;
      case kNormals:
        read_vectors(in, kw, m.normals);
        break;
      case kTangents:
        read_vectors(in, kw, m.tangents);
        break;
      case kNormalAtVertices:
        read_pairs(in, kw, code, m.normal_at_vertex, Bound::kNormal, out);
        break;
      case kTangentAtVertices:
        read_pairs(in, kw, code, m.tangent_at_vertex, Bound::kTangent, out);
        break;
      default:
        in.skip_section(kw);
        break;
    }
  }
  if (in.dim() == 0) fail(path, "Dimension", "missing (not a Medit mesh file?)");
  m.dim = in.dim();
  return out.finish(options);
}

namespace {

void write_ids(io_detail::TextOut& out, const char* kw, const std::vector<Id>& ids) {
  if (ids.empty()) return;
  out.text("\n").text(kw).text("\n").integer(static_cast<std::int64_t>(ids.size())).text("\n");
  for (Id id : ids) out.integer(std::int64_t{id} + 1).text("\n");
}

void write_elements(io_detail::TextOut& out, const char* kw, const std::vector<Id>& ids,
                    const std::vector<std::int32_t>& refs, int nodes) {
  if (ids.empty()) return;
  const std::size_t n = ids.size() / nodes;
  out.text("\n").text(kw).text("\n").integer(static_cast<std::int64_t>(n)).text("\n");
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < nodes; ++k) out.integer(std::int64_t{ids[i * nodes + k]} + 1).text(" ");
    out.integer(ref_at(refs, i)).text("\n");
  }
}

void write_vectors(io_detail::TextOut& out, const char* kw, const std::vector<double>& values,
                   int dim) {
  if (values.empty()) return;
  const std::size_t n = values.size() / 3;
  out.text("\n").text(kw).text("\n").integer(static_cast<std::int64_t>(n)).text("\n");
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) out.real(values[3 * i + k]).text(k + 1 < dim ? " " : "\n");
  }
}

void write_pairs(io_detail::TextOut& out, const char* kw, const std::vector<Id>& ids) {
  if (ids.empty()) return;
  out.text("\n").text(kw).text("\n").integer(static_cast<std::int64_t>(ids.size() / 2)).text("\n");
  for (std::size_t i = 0; i < ids.size(); i += 2)
    out.integer(std::int64_t{ids[i]} + 1)
        .text(" ")
        .integer(std::int64_t{ids[i + 1]} + 1)
        .text("\n");
}

}  // namespace

void write_medit_ascii(const Mesh& mesh, AtomicFile& file, const MeditWriteOptions& options) {
  io_detail::TextOut out(file);
  const int dim = mesh.dim;
  out.text("MeshVersionFormatted 2\n\nDimension ").integer(dim).text("\n");
  const std::size_t nv = mesh.num_vertices();
  if (nv > 0) {
    out.text("\nVertices\n").integer(static_cast<std::int64_t>(nv)).text("\n");
    for (std::size_t v = 0; v < nv; ++v) {
      for (int k = 0; k < dim; ++k) out.real(mesh.coords[v * dim + k]).text(" ");
      out.integer(ref_at(mesh.vert_ref, v)).text("\n");
    }
  }
  write_elements(out, "Edges", mesh.edges, mesh.edge_ref, 2);
  write_elements(out, "Triangles", output_triangles(mesh, options.ccw_2d), mesh.tri_ref, 3);
  write_elements(out, "Tetrahedra", mesh.tets, mesh.tet_ref, 4);
  write_ids(out, "Corners", tagged(mesh.vert_tag, kTagCorner));
  write_ids(out, "RequiredVertices", tagged(mesh.vert_tag, kTagRequired));
  write_ids(out, "Ridges", tagged(mesh.edge_tag, kTagRidge));
  write_ids(out, "RequiredEdges", tagged(mesh.edge_tag, kTagRequired));
  write_ids(out, "RequiredTriangles", tagged(mesh.tri_tag, kTagRequired));
  write_vectors(out, "Normals", mesh.normals, dim);
  write_pairs(out, "NormalAtVertices", mesh.normal_at_vertex);
  write_vectors(out, "Tangents", mesh.tangents, dim);
  write_pairs(out, "TangentAtVertices", mesh.tangent_at_vertex);
  out.text("\nEnd\n");
  out.flush();
}

}  // namespace riemesh::medit_detail
