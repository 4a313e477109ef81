// Writing MSH 4.1, ASCII or binary. Each distinct ref of each element dimension becomes one
// entity with one physical group (see gmsh.hpp); elements are written grouped by ref, keeping
// their relative order, so a mesh whose elements are sorted by ref reads back identically.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/gmsh.hpp"
#include "io/medit_detail.hpp"
#include "io/text_out.hpp"

namespace riemesh {

namespace {

using medit_detail::ref_at;

// One entity: the elements of one dimension that share a ref.
struct Entity {
  int tag = 0;
  int physical = 0;
  bool physical_group = true;  // false: no physical group (the unused point of an empty mesh)
  std::vector<Id> elements;    // ids into the mesh arrays (vertices for points)
  std::array<double, 6> box{};
};

// Values in ASCII (space separated, one record per line) or binary (native little-endian
// int32, uint64 size_t and double), through the same calls.
class MshOut {
 public:
  MshOut(AtomicFile& file, bool binary) : out_(file), binary_(binary) {}
  void text(std::string_view s) { out_.text(s); }
  void size(std::uint64_t v) {
    if (binary_)
      put(v);
    else
      sep().integer(static_cast<std::int64_t>(v));
  }
  void int32(std::int32_t v) {
    if (binary_)
      put(v);
    else
      sep().integer(v);
  }
  void real(double v) {
    if (binary_)
      put(v);
    else
      sep().real(v);
  }
  void end_line() {
    if (binary_) return;
    out_.text("\n");
    first_ = true;
  }
  void begin_section(std::string_view name) {
    std::string line = "$";
    line += name;
    line += '\n';
    out_.text(line);
    first_ = true;
  }
  void end_section(std::string_view name) {
    std::string line = binary_ ? "\n$End" : "$End";
    line += name;
    line += '\n';
    out_.text(line);
  }
  void flush() { out_.flush(); }

 private:
  template <class T>
  void put(T v) {
    out_.text(std::string_view(reinterpret_cast<const char*>(&v), sizeof v));
  }
  io_detail::TextOut& sep() {
    if (!first_) out_.text(" ");
    first_ = false;
    return out_;
  }
  io_detail::TextOut out_;
  bool binary_;
  bool first_ = true;
};

// Entities of one dimension from the refs of its n elements (of `nodes` vertices each).
std::vector<Entity> make_entities(const Mesh& mesh, const std::vector<std::int32_t>& refs,
                                  const std::vector<Id>& elements, int nodes, std::size_t n) {
  std::map<std::int32_t, std::size_t> index;  // ref -> entity
  std::vector<Entity> entities;
  for (std::size_t e = 0; e < n; ++e) {
    const std::int32_t ref = ref_at(refs, e);
    auto [it, inserted] = index.emplace(ref, entities.size());
    if (inserted) {
      entities.emplace_back();
      entities.back().physical = ref;
      entities.back().box = {
          std::numeric_limits<double>::max(),  std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max(),  -std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    }
    Entity& entity = entities[it->second];
    entity.elements.push_back(static_cast<Id>(e));
    for (int k = 0; k < nodes; ++k) {
      const Id v = nodes == 1 ? static_cast<Id>(e) : elements[e * nodes + k];
      for (int c = 0; c < 3; ++c) {
        const double x = c < mesh.dim ? mesh.coords[static_cast<std::size_t>(v) * mesh.dim + c] : 0;
        entity.box[c] = std::min(entity.box[c], x);
        entity.box[c + 3] = std::max(entity.box[c + 3], x);
      }
    }
  }
  // Entity tags must be positive: a positive ref is its own tag, the others get unused ones.
  std::int32_t next = 1;
  for (const Entity& entity : entities) next = std::max(next, entity.physical + 1);
  std::sort(entities.begin(), entities.end(),
            [](const Entity& a, const Entity& b) { return a.physical < b.physical; });
  for (Entity& entity : entities) entity.tag = entity.physical > 0 ? entity.physical : next++;
  return entities;
}

void write_entities(MshOut& out, const std::array<std::vector<Entity>, 4>& entities) {
  out.begin_section("Entities");
  for (const auto& list : entities) out.size(list.size());
  out.end_line();
  for (int dim = 0; dim < 4; ++dim)
    for (const Entity& entity : entities[dim]) {
      out.int32(entity.tag);
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) out.real(entity.box[c]);
      out.size(entity.physical_group ? 1 : 0);
      if (entity.physical_group) out.int32(entity.physical);
      if (dim > 0) out.size(0);  // no bounding entities: a discrete mesh
      out.end_line();
    }
  out.end_section("Entities");
}

void write_nodes(MshOut& out, const Mesh& mesh, int entity_dim, int entity_tag) {
  const std::size_t nv = mesh.num_vertices();
  out.begin_section("Nodes");
  out.size(nv ? 1 : 0);
  out.size(nv);
  out.size(nv ? 1 : 0);
  out.size(nv);
  out.end_line();
  if (nv) {
    out.int32(entity_dim);
    out.int32(entity_tag);
    out.int32(0);
    out.size(nv);
    out.end_line();
    for (std::size_t v = 0; v < nv; ++v) {
      out.size(v + 1);
      out.end_line();
    }
    for (std::size_t v = 0; v < nv; ++v) {
      for (int c = 0; c < 3; ++c) out.real(c < mesh.dim ? mesh.coords[v * mesh.dim + c] : 0.0);
      out.end_line();
    }
  }
  out.end_section("Nodes");
}

void write_elements(MshOut& out, const Mesh& mesh,
                    const std::array<std::vector<Entity>, 4>& entities) {
  static constexpr int kType[4] = {15, 1, 2, 4};
  static constexpr int kNodes[4] = {1, 2, 3, 4};
  const std::vector<Id>* arrays[4] = {nullptr, &mesh.edges, &mesh.triangles, &mesh.tets};
  std::size_t blocks = 0, total = 0;
  for (const auto& list : entities)
    for (const Entity& entity : list) {
      ++blocks;
      total += entity.elements.size();
    }
  out.begin_section("Elements");
  out.size(blocks);
  out.size(total);
  out.size(total ? 1 : 0);
  out.size(total);
  out.end_line();
  std::uint64_t tag = 0;
  for (int dim = 0; dim < 4; ++dim)
    for (const Entity& entity : entities[dim]) {
      out.int32(dim);
      out.int32(entity.tag);
      out.int32(kType[dim]);
      out.size(entity.elements.size());
      out.end_line();
      for (Id e : entity.elements) {
        out.size(++tag);
        for (int k = 0; k < kNodes[dim]; ++k) {
          const Id v = dim == 0 ? e : (*arrays[dim])[static_cast<std::size_t>(e) * kNodes[dim] + k];
          out.size(static_cast<std::uint64_t>(v) + 1);
        }
        out.end_line();
      }
    }
  out.end_section("Elements");
}

// A $NodeData view: 1, 3 or 9 (full 3x3 tensor, row by row) components per node.
void write_node_data(MshOut& out, const Mesh& mesh, const Field& field) {
  const std::size_t nv = mesh.num_vertices();
  const int dim = mesh.dim;
  const int nc = field_components(field.kind, dim);
  if (field.values.size() != nv * static_cast<std::size_t>(nc))
    throw Error("cannot write field '" + field.name + "': " + std::to_string(field.values.size()) +
                " values for " + std::to_string(nv) + " vertices");
  const int components = field.kind == FieldKind::kScalar   ? 1
                         : field.kind == FieldKind::kVector ? 3
                                                            : 9;
  std::string name;
  for (char c : field.name) name += (c == '"' || static_cast<unsigned char>(c) < 32) ? '_' : c;
  std::string header = "1\n\"";
  header += name;
  header += "\"\n1\n0\n3\n0\n";
  header += std::to_string(components);
  header += '\n';
  header += std::to_string(nv);
  header += '\n';
  out.begin_section("NodeData");
  out.text(header);
  for (std::size_t v = 0; v < nv; ++v) {
    const double* a = field.values.data() + v * static_cast<std::size_t>(nc);
    double full[9] = {};
    if (field.kind == FieldKind::kScalar) {
      full[0] = a[0];
    } else if (field.kind == FieldKind::kVector) {
      std::copy(a, a + nc, full);
    } else {
      // Packed m11 m12 m22 (m13 m23 m33) -> symmetric 3x3, zero third row/column in 2D.
      full[0] = a[0], full[1] = full[3] = a[1], full[4] = a[2];
      if (dim == 3) full[2] = full[6] = a[3], full[5] = full[7] = a[4], full[8] = a[5];
    }
    out.int32(static_cast<std::int32_t>(v + 1));
    for (int k = 0; k < components; ++k) out.real(full[k]);
    out.end_line();
  }
  out.end_section("NodeData");
}

}  // namespace

void write_gmsh(const Mesh& mesh, const std::string& path, const GmshWriteOptions& options) {
  medit_detail::check_writable(mesh, path);
  if (mesh.num_vertices() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw Error(path + ": cannot write mesh: too many vertices for $NodeData int tags");
  std::array<std::vector<Entity>, 4> entities;
  std::vector<std::int32_t> corner_refs;
  std::vector<Id> corners = medit_detail::tagged(mesh.vert_tag, kTagCorner);
  for (Id v : corners) corner_refs.push_back(ref_at(mesh.vert_ref, static_cast<std::size_t>(v)));
  entities[0] = make_entities(mesh, corner_refs, {}, 1, corners.size());
  for (Entity& entity : entities[0])
    for (Id& e : entity.elements) e = corners[static_cast<std::size_t>(e)];
  // The point box is the point itself: that of its first corner.
  for (Entity& entity : entities[0])
    for (int c = 0; c < 3; ++c)
      entity.box[c] = c < mesh.dim
                          ? mesh.coords[static_cast<std::size_t>(entity.elements[0]) * mesh.dim + c]
                          : 0.0;
  entities[1] = make_entities(mesh, mesh.edge_ref, mesh.edges, 2, mesh.num_edges());
  entities[2] = make_entities(mesh, mesh.tri_ref, mesh.triangles, 3, mesh.num_triangles());
  entities[3] = make_entities(mesh, mesh.tet_ref, mesh.tets, 4, mesh.num_tets());

  // All nodes in one block, on the first entity of the highest dimension (gmsh accepts nodes
  // classified on any entity; a mesh without elements gets an unused point entity).
  int node_dim = 3;
  while (node_dim > 0 && entities[node_dim].empty()) --node_dim;
  if (entities[node_dim].empty() && mesh.num_vertices() > 0) {
    Entity point;
    point.tag = 1;
    point.physical_group = false;
    entities[0].push_back(point);
  }
  const int node_tag = entities[node_dim].empty() ? 1 : entities[node_dim][0].tag;

  AtomicFile file(path, options.sync);
  MshOut out(file, options.binary);
  out.text(options.binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n");
  if (options.binary) {
    out.int32(1);
    out.text("\n");
  }
  out.text("$EndMeshFormat\n");
  write_entities(out, entities);
  write_nodes(out, mesh, node_dim, node_tag);
  write_elements(out, mesh, entities);
  if (options.fields)
    for (const Field& field : mesh.fields) write_node_data(out, mesh, field);
  out.flush();
  file.commit();
}

}  // namespace riemesh
