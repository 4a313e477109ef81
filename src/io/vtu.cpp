#include "io/vtu.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medit_detail.hpp"

namespace riemesh {

namespace {

constexpr std::uint8_t kVtkLine = 3, kVtkTriangle = 5, kVtkTetra = 10;

// One appended array: its XML element and its raw bytes.
struct Array {
  std::string element;  // without the offset attribute and the closing "/>"
  std::string bytes;
};

template <class T>
Array make_array(const char* type, const std::string& name, int components,
                 const std::vector<T>& values) {
  Array a;
  a.element = "<DataArray type=\"";
  a.element += type;
  a.element += '"';
  if (!name.empty()) {
    a.element += " Name=\"";
    a.element += name;
    a.element += '"';
  }
  a.element += " NumberOfComponents=\"";
  a.element += std::to_string(components);
  a.element += "\" format=\"appended\"";
  a.bytes.resize(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), a.bytes.size());
  return a;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += static_cast<unsigned char>(c) < 32 ? '_' : c;
    }
  }
  return out;
}

// A field as VTK components: scalars 1, vectors 3, symmetric tensors 6 (XX YY ZZ XY YZ XZ).
Array field_array(const Mesh& mesh, const Field& field, const std::string& path) {
  const std::size_t nv = mesh.num_vertices();
  const int dim = mesh.dim;
  const auto nc = static_cast<std::size_t>(field_components(field.kind, dim));
  if (field.values.size() != nv * nc)
    throw Error(path + ": cannot write field '" + field.name +
                "': " + std::to_string(field.values.size()) + " values for " + std::to_string(nv) +
                " vertices");
  const int components = field.kind == FieldKind::kScalar   ? 1
                         : field.kind == FieldKind::kVector ? 3
                                                            : 6;
  std::vector<double> out(nv * static_cast<std::size_t>(components), 0.0);
  for (std::size_t v = 0; v < nv; ++v) {
    const double* a = field.values.data() + v * nc;
    double* o = out.data() + v * static_cast<std::size_t>(components);
    if (field.kind == FieldKind::kScalar) {
      o[0] = a[0];
    } else if (field.kind == FieldKind::kVector) {
      for (int k = 0; k < dim; ++k) o[k] = a[k];
    } else if (dim == 2) {  // m11 m12 m22
      o[0] = a[0], o[1] = a[2], o[3] = a[1];
    } else {  // m11 m12 m22 m13 m23 m33
      o[0] = a[0], o[1] = a[2], o[2] = a[5], o[3] = a[1], o[4] = a[4], o[5] = a[3];
    }
  }
  return make_array("Float64", xml_escape(field.name), components, out);
}

}  // namespace

void write_vtu(const Mesh& mesh, const std::string& path, const VtuWriteOptions& options) {
  medit_detail::check_writable(mesh, path);
  const std::size_t nv = mesh.num_vertices();
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_triangles(), ne = mesh.num_edges();
  const std::size_t num_cells = nt + nf + ne;

  std::vector<double> points(3 * nv, 0.0);
  for (std::size_t v = 0; v < nv; ++v)
    for (int c = 0; c < mesh.dim; ++c) points[3 * v + c] = mesh.coords[v * mesh.dim + c];
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types, dims;
  std::vector<std::int32_t> refs;
  connectivity.reserve(4 * nt + 3 * nf + 2 * ne);
  offsets.reserve(num_cells);
  auto add = [&](const std::vector<Id>& ids, const std::vector<std::int32_t>& ref, int nodes,
                 std::uint8_t type) {
    const std::size_t n = ids.size() / nodes;
    for (std::size_t e = 0; e < n; ++e) {
      for (int k = 0; k < nodes; ++k) connectivity.push_back(ids[e * nodes + k]);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(type);
      dims.push_back(static_cast<std::uint8_t>(nodes - 1));
      refs.push_back(medit_detail::ref_at(ref, e));
    }
  };
  add(mesh.tets, mesh.tet_ref, 4, kVtkTetra);
  add(mesh.triangles, mesh.tri_ref, 3, kVtkTriangle);
  add(mesh.edges, mesh.edge_ref, 2, kVtkLine);
  std::vector<std::int32_t> vert_ref(nv, 0);
  for (std::size_t v = 0; v < mesh.vert_ref.size(); ++v) vert_ref[v] = mesh.vert_ref[v];

  std::vector<Array> point_data, cell_data, geometry, cells;
  point_data.push_back(make_array("Int32", "ref", 1, vert_ref));
  for (const Field& field : mesh.fields) {
    // A field called "ref" gave the file two point arrays of that name: it becomes "ref_field".
    if (field.name != "ref") {
      point_data.push_back(field_array(mesh, field, path));
      continue;
    }
    Field renamed = field;
    renamed.name = "ref_field";
    point_data.push_back(field_array(mesh, renamed, path));
  }
  cell_data.push_back(make_array("Int32", "ref", 1, refs));
  cell_data.push_back(make_array("UInt8", "dim", 1, dims));
  geometry.push_back(make_array("Float64", "", 3, points));
  cells.push_back(make_array("Int64", "connectivity", 1, connectivity));
  cells.push_back(make_array("Int64", "offsets", 1, offsets));
  cells.push_back(make_array("UInt8", "types", 1, types));

  // XML first, with each array's offset into the appended data (8-byte size header + data).
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" ";
  xml += std::endian::native == std::endian::little ? "byte_order=\"LittleEndian\""
                                                    : "byte_order=\"BigEndian\"";
  xml += " header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"";
  xml += std::to_string(nv);
  xml += "\" NumberOfCells=\"";
  xml += std::to_string(num_cells);
  xml += "\">\n";
  std::uint64_t offset = 0;
  auto section = [&](const char* tag, const std::vector<Array>& arrays) {
    xml += '<';
    xml += tag;
    xml += ">\n";
    for (const Array& a : arrays) {
      xml += a.element;
      xml += " offset=\"";
      xml += std::to_string(offset);
      xml += "\"/>\n";
      offset += 8 + a.bytes.size();
    }
    xml += "</";
    xml += tag;
    xml += ">\n";
  };
  section("PointData", point_data);
  section("CellData", cell_data);
  section("Points", geometry);
  section("Cells", cells);
  xml += "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";

  AtomicFile file(path, options.sync);
  file.write(xml);
  for (const auto* arrays : {&point_data, &cell_data, &geometry, &cells})
    for (const Array& a : *arrays) {
      const std::uint64_t size = a.bytes.size();
      file.write(&size, sizeof size);
      file.write(a.bytes);
    }
  file.write(std::string_view("\n</AppendedData>\n</VTKFile>\n"));
  file.commit();
}

}  // namespace riemesh
