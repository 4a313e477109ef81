#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "io/medit_detail.hpp"
#include "io/text_scanner.hpp"

namespace riemesh::medit_detail {

namespace {

struct NamedCode {
  int code;
  const char* name;
};

constexpr NamedCode kKeywords[] = {
    {kVersionFormatted, "MeshVersionFormatted"},
    {kDimension, "Dimension"},
    {kVertices, "Vertices"},
    {kEdges, "Edges"},
    {kTriangles, "Triangles"},
    {kTetrahedra, "Tetrahedra"},
    {kCorners, "Corners"},
    {kRidges, "Ridges"},
    {kRequiredVertices, "RequiredVertices"},
    {kRequiredEdges, "RequiredEdges"},
    {kRequiredTriangles, "RequiredTriangles"},
    {kNormalAtVertices, "NormalAtVertices"},
    {kEnd, "End"},
    {kTangents, "Tangents"},
    {kNormals, "Normals"},
    {kTangentAtVertices, "TangentAtVertices"},
    {kSolAtVertices, "SolAtVertices"},
    {kSolAtTriangles, "SolAtTriangles"},
    {kSolAtTetrahedra, "SolAtTetrahedra"},
};

struct SkippedKeyword {
  const char* name;
  int ints;
  int code;  // libMeshb's GmfKwdCod (medit_detail.hpp)
};

// Element keywords of libMeshb (GmfKwdFmt) with a fixed number of integers per entry. FreeFem's
// BAMG keywords (SubDomainFromGeom has 4 ints there but 3 in libMeshb) are not listed: the
// ASCII reader skips unlisted keywords by scanning to the next word.
constexpr SkippedKeyword kSkipped[] = {
    {"Quadrilaterals", 5, 7}, {"Prisms", 7, 9},
    {"Hexahedra", 9, 10},     {"Pyramids", 6, 49},
    {"EdgesP2", 4, 25},       {"TrianglesP2", 7, 24},
    {"TetrahedraP2", 11, 30}, {"QuadrilateralsQ2", 10, 27},
    {"HexahedraQ2", 28, 33},  {"RequiredQuadrilaterals", 1, 18},
};

const char* bound_name(Bound b) {
  switch (b) {
    case Bound::kVertex:
      return "vertex";
    case Bound::kEdge:
      return "edge";
    case Bound::kTriangle:
      return "triangle";
    case Bound::kNormal:
      return "normal";
    case Bound::kTangent:
      return "tangent";
  }
  return "";
}

const char* bound_plural(Bound b) {
  return b == Bound::kVertex     ? "vertices"
         : b == Bound::kEdge     ? "edges"
         : b == Bound::kTriangle ? "triangles"
         : b == Bound::kNormal   ? "normals"
                                 : "tangents";
}

}  // namespace

int keyword_code(std::string_view name) {
  for (const NamedCode& k : kKeywords)
    if (io_detail::iequals(name, k.name)) return k.code;
  return 0;
}

const char* keyword_name(int code) {
  for (const NamedCode& k : kKeywords)
    if (k.code == code) return k.name;
  return "keyword";
}

int skipped_keyword_ints(std::string_view name) {
  for (const SkippedKeyword& k : kSkipped)
    if (io_detail::iequals(name, k.name)) return k.ints;
  return -1;
}

const char* skipped_keyword(int code, int& ints) {
  for (const SkippedKeyword& k : kSkipped)
    if (k.code == code) {
      ints = k.ints;
      return k.name;
    }
  return nullptr;
}

bool known_skipped_keyword(std::string_view name) {
  static constexpr std::string_view kKnown[] = {"Identifier",
                                                "Geometry",
                                                "VertexOnGeometricVertex",
                                                "VertexOnGeometricEdge",
                                                "EdgeOnGeometricEdge",
                                                "SubDomain",
                                                "SubDomainFromMesh",
                                                "SubDomainFromGeom",
                                                "CrackedEdges",
                                                "MaximalAngleOfCorner",
                                                "AngleOfCornerBound",
                                                "hVertices",
                                                "MetricAtVertices",
                                                "VertexOnSupportEdge",
                                                "VertexOnSupportTriangle",
                                                "VertexOnSupportTetrahedron",
                                                "Cracks",
                                                "EquivalentEdges",
                                                "VertexOnGeometricFace",
                                                "EdgeOnGeometricFace",
                                                "RequiredVerticesGeom",
                                                "Boundingbox",
                                                "Time",
                                                "Iterations",
                                                "SolAtVertices",
                                                "SolAtEdges",
                                                "SolAtTriangles",
                                                "SolAtTetrahedra",
                                                "Reference",
                                                "Polygons",
                                                "Polyhedra",
                                                "Curvatures",
                                                "CornersGeom",
                                                "RidgesGeom",
                                                "TangentAtEdges",
                                                "NormalAtTriangleVertices",
                                                "NormalAtQuadrilateralVertices",
                                                "RequiredTetrahedra",
                                                "RequiredHexahedra",
                                                "VerticesOnGeometricVertices",
                                                "VerticesOnGeometricEdges",
                                                "VerticesOnGeometricTriangles",
                                                "EdgesOnGeometricEdges",
                                                "TrianglesOnGeometricTriangles"};
  for (const std::string_view k : kKnown)
    if (io_detail::iequals(name, k)) return true;
  return skipped_keyword_ints(name) > 0;  // (element keywords: Quadrilaterals, Prisms, ...)
}

bool holds_elements(std::string_view name) {
  return !io_detail::iequals(name, "RequiredQuadrilaterals");
}

std::string unread_elements(std::size_t n) {
  return std::to_string(n) +
         " elements of a kind riemesh does not read (it reads linear Edges, Triangles and "
         "Tetrahedra only)";
}

std::string quote(std::string_view token) {
  std::string s = "'";
  for (std::size_t i = 0; i < token.size() && i < 40; ++i) {
    const char c = token[i];
    s += (c >= 32 && c < 127) ? c : '?';
  }
  if (token.size() > 40) s += "...";
  return s + "'";
}

void fail(const std::string& where, std::string_view keyword, const std::string& what) {
  std::string message = where + ": ";
  if (!keyword.empty()) message.append(keyword).append(": ");
  throw InputError(message + what);
}

std::vector<Id>& MeshAssembler::tag_list(int code) {
  switch (code) {
    case kCorners:
      return corners;
    case kRequiredVertices:
      return required_vertices;
    case kRidges:
      return ridges;
    case kRequiredEdges:
      return required_edges;
    default:
      return required_triangles;
  }
}

void MeshAssembler::add_block(int code, std::vector<Id>& ids, std::size_t begin, int stride,
                              std::array<Bound, 4> bounds, Locator locate) {
  blocks.push_back(IdBlock{code, &ids, begin, ids.size(), stride, bounds, std::move(locate)});
}

Mesh MeshAssembler::finish(const MeditReadOptions& options) {
  const std::size_t nv = mesh.num_vertices();
  const std::size_t limits[] = {nv, mesh.num_edges(), mesh.num_triangles(), mesh.normals.size() / 3,
                                mesh.tangents.size() / 3};
  for (const IdBlock& b : blocks) {
    const std::vector<Id>& ids = *b.ids;
    for (std::size_t i = b.begin; i < b.end; ++i) {
      const std::size_t column = (i - b.begin) % b.stride;
      const Bound bound = b.bounds[column];
      const std::size_t limit = limits[static_cast<int>(bound)];
      if (ids[i] >= 0 && static_cast<std::size_t>(ids[i]) < limit) continue;
      const std::size_t entry = (i - b.begin) / b.stride;
      fail(b.locate(entry, static_cast<int>(column)), keyword_name(b.code),
           std::string(bound_name(bound)) + " id " + std::to_string(std::int64_t{ids[i]} + 1) +
               " out of range (the file has " + std::to_string(limit) + " " +
               (limit == 1 ? bound_name(bound) : bound_plural(bound)) + ")");
    }
  }
  mesh.vert_tag.assign(nv, kTagNone);
  mesh.edge_tag.assign(mesh.num_edges(), kTagNone);
  mesh.tri_tag.assign(mesh.num_triangles(), kTagNone);
  for (Id v : corners) mesh.vert_tag[v] |= kTagCorner;
  for (Id v : required_vertices) mesh.vert_tag[v] |= kTagRequired;
  for (Id e : ridges) mesh.edge_tag[e] |= kTagRidge;
  for (Id e : required_edges) mesh.edge_tag[e] |= kTagRequired;
  for (Id t : required_triangles) mesh.tri_tag[t] |= kTagRequired;
  if (options.planar_as_2d) make_planar(mesh);
  return std::move(mesh);
}

bool make_planar(Mesh& mesh) {
  if (mesh.dim != 3 || !mesh.tets.empty() || !mesh.normals.empty() || !mesh.tangents.empty() ||
      mesh.num_vertices() == 0)
    return false;
  const std::size_t nv = mesh.num_vertices();
  for (std::size_t v = 0; v < nv; ++v)
    if (mesh.coords[3 * v + 2] != 0.0) return false;
  std::vector<double> xy(2 * nv);
  for (std::size_t v = 0; v < nv; ++v) {
    xy[2 * v] = mesh.coords[3 * v];
    xy[2 * v + 1] = mesh.coords[3 * v + 1];
  }
  // Gmsh orients a 2D mesh as its curve loops: all counter-clockwise, or all clockwise (a loop
  // given clockwise), which is the same mesh mirrored and is read turned over (it was called
  // inverted by `check` and turned over by `convert` only), or, with several surfaces, each
  // surface (triangle ref) its own way: its clockwise ones are turned over too (such a mesh
  // was read as a surface lying in z = 0 and adapted as one, a 3D output: QA hunt 5 F11).
  // Triangles of both orientations within one ref are no planar mesh but a surface that lies
  // in z = 0: it stays one.
  const std::size_t nt = mesh.num_triangles();
  const bool refs = mesh.tri_ref.size() == nt;
  std::map<std::int32_t, std::pair<std::size_t, std::size_t>> by_ref;  // ref -> (ccw, cw)
  std::vector<std::uint8_t> clockwise(nt, 0);
  std::size_t cw = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const double* a = &xy[2 * static_cast<std::size_t>(mesh.triangles[3 * t])];
    const double* b = &xy[2 * static_cast<std::size_t>(mesh.triangles[3 * t + 1])];
    const double* c = &xy[2 * static_cast<std::size_t>(mesh.triangles[3 * t + 2])];
    const double area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    auto& n = by_ref[refs ? mesh.tri_ref[t] : 0];
    n.first += area2 > 0.0, n.second += area2 < 0.0;
    clockwise[t] = area2 < 0.0;
    cw += clockwise[t];
  }
  for (const auto& [ref, n] : by_ref)
    if (n.first > 0 && n.second > 0) return false;
  for (std::size_t t = 0; t < nt; ++t)
    if (clockwise[t]) std::swap(mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]);
  if (cw == nt && cw > 0)  // (all turned: the edges with them, as the domain's boundary)
    for (std::size_t e = 0; e < mesh.edges.size(); e += 2)
      std::swap(mesh.edges[e], mesh.edges[e + 1]);
  mesh.coords = std::move(xy);
  mesh.dim = 2;
  return true;
}

void check_writable(const Mesh& mesh, const std::string& path) {
  auto bad = [&](const std::string& what) { throw Error(path + ": cannot write mesh: " + what); };
  if (mesh.dim != 2 && mesh.dim != 3) bad("dimension " + std::to_string(mesh.dim));
  if (mesh.coords.size() % mesh.dim != 0) bad("coords size is not a multiple of dim");
  const std::size_t nv = mesh.num_vertices();
  if (mesh.edges.size() % 2 || mesh.triangles.size() % 3 || mesh.tets.size() % 4)
    bad("connectivity size is not a multiple of the element size");
  if (mesh.dim == 2 && !mesh.tets.empty()) bad("tetrahedra in a planar mesh");
  auto sized = [&](std::size_t size, std::size_t n, const char* name) {
    if (size != 0 && size != n) bad(std::string(name) + " size does not match");
  };
  sized(mesh.vert_ref.size(), nv, "vert_ref");
  sized(mesh.vert_tag.size(), nv, "vert_tag");
  sized(mesh.edge_ref.size(), mesh.num_edges(), "edge_ref");
  sized(mesh.edge_tag.size(), mesh.num_edges(), "edge_tag");
  sized(mesh.tri_ref.size(), mesh.num_triangles(), "tri_ref");
  sized(mesh.tri_tag.size(), mesh.num_triangles(), "tri_tag");
  sized(mesh.tet_ref.size(), mesh.num_tets(), "tet_ref");
  if (mesh.normals.size() % 3 || mesh.tangents.size() % 3) bad("normals/tangents size");
  if (mesh.normal_at_vertex.size() % 2 || mesh.tangent_at_vertex.size() % 2)
    bad("normal_at_vertex/tangent_at_vertex size");
  auto in_range = [&](const std::vector<Id>& ids, std::size_t stride, std::size_t column,
                      std::size_t n, const char* name) {
    for (std::size_t i = column; i < ids.size(); i += stride)
      if (ids[i] < 0 || static_cast<std::size_t>(ids[i]) >= n)
        bad(std::string(name) + " id out of range");
  };
  in_range(mesh.edges, 1, 0, nv, "edge vertex");
  in_range(mesh.triangles, 1, 0, nv, "triangle vertex");
  in_range(mesh.tets, 1, 0, nv, "tetrahedron vertex");
  in_range(mesh.normal_at_vertex, 2, 0, nv, "normal_at_vertex vertex");
  in_range(mesh.normal_at_vertex, 2, 1, mesh.normals.size() / 3, "normal_at_vertex normal");
  in_range(mesh.tangent_at_vertex, 2, 0, nv, "tangent_at_vertex vertex");
  in_range(mesh.tangent_at_vertex, 2, 1, mesh.tangents.size() / 3, "tangent_at_vertex tangent");
  for (double x : mesh.coords)
    if (!std::isfinite(x)) bad("non-finite coordinate");
}

std::vector<Id> tagged(const std::vector<std::uint8_t>& tags, std::uint8_t bit) {
  std::vector<Id> ids;
  for (std::size_t i = 0; i < tags.size(); ++i)
    if (tags[i] & bit) ids.push_back(static_cast<Id>(i));
  return ids;
}

std::vector<Id> output_triangles(const Mesh& mesh, bool ccw) {
  std::vector<Id> tris = mesh.triangles;
  if (!ccw || mesh.dim != 2) return tris;
  const double* x = mesh.coords.data();
  for (std::size_t t = 0; t < tris.size(); t += 3) {
    const Id a = tris[t], b = tris[t + 1], c = tris[t + 2];
    const double area2 = (x[2 * b] - x[2 * a]) * (x[2 * c + 1] - x[2 * a + 1]) -
                         (x[2 * b + 1] - x[2 * a + 1]) * (x[2 * c] - x[2 * a]);
    if (area2 < 0) std::swap(tris[t + 1], tris[t + 2]);
  }
  return tris;
}

bool ends_with(const std::string& path, std::string_view suffix) {
  return path.size() >= suffix.size() &&
         std::string_view(path).substr(path.size() - suffix.size()) == suffix;
}

}  // namespace riemesh::medit_detail
