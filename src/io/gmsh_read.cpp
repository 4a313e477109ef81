// Reading MSH 4.1 sections ($Entities, $Nodes, $Elements) and the file's section loop. The same
// code reads ASCII and binary files: in both the spec lists the same values in the same order.
#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/gmsh_detail.hpp"
#include "io/medit_detail.hpp"

namespace riemesh {
namespace gmsh_detail {

namespace {

constexpr std::uint64_t kMaxIds = std::numeric_limits<Id>::max();

bool kept_type(int type) {
  return type == kPoint || type == kLine || type == kTriangle || type == kTetrahedron;
}

}  // namespace

int GmshAssembler::ref_of(int dim, int tag) const {
  const auto it = entity_ref.find({dim, tag});
  return it == entity_ref.end() ? tag : it->second;
}

Id GmshAssembler::node(std::uint64_t tag, const GmshInput& input) const {
  const Id v = nodes.find(tag);
  if (v == kNoId) input.fail("unknown node tag " + std::to_string(tag));
  return v;
}

void GmshAssembler::add(int type, const Id* v, int ref) {
  switch (type) {
    case kPoint:
      mesh.vert_tag[v[0]] |= kTagCorner;
      mesh.vert_ref[v[0]] = ref;
      break;
    case kLine:
      mesh.edges.insert(mesh.edges.end(), v, v + 2);
      mesh.edge_ref.push_back(ref);
      break;
    case kTriangle:
      mesh.triangles.insert(mesh.triangles.end(), v, v + 3);
      mesh.tri_ref.push_back(ref);
      break;
    default:
      mesh.tets.insert(mesh.tets.end(), v, v + 4);
      mesh.tet_ref.push_back(ref);
  }
}

void GmshAssembler::end_nodes(const std::vector<std::uint64_t>& tags, GmshInput& input) {
  input.end_data();
  input.expect_end("Nodes");
  nodes.build(tags, input);
  mesh.vert_ref.assign(tags.size(), 0);
  mesh.vert_tag.assign(tags.size(), kTagNone);
  have_nodes = true;
}

Mesh GmshAssembler::finish(const GmshReadOptions& options, GmshReadInfo* info) {
  mesh.edge_tag.assign(mesh.num_edges(), kTagNone);
  mesh.tri_tag.assign(mesh.num_triangles(), kTagNone);
  if (options.planar_as_2d) medit_detail::make_planar(mesh);
  const int dim = mesh.dim;
  const std::size_t nv = mesh.num_vertices();
  for (RawField& raw : fields) {
    Field f;
    f.name = raw.name;
    f.kind = raw.components == 1   ? FieldKind::kScalar
             : raw.components == 3 ? FieldKind::kVector
                                   : FieldKind::kSymTensor;
    const int nc = field_components(f.kind, dim);
    f.values.resize(nv * static_cast<std::size_t>(nc));
    for (std::size_t v = 0; v < nv; ++v) {
      const double* a = raw.values.data() + v * static_cast<std::size_t>(raw.components);
      double* out = f.values.data() + v * static_cast<std::size_t>(nc);
      if (f.kind == FieldKind::kSymTensor) {
        // Full 3x3 row by row -> packed m11 m12 m22 (m13 m23 m33), upper triangle.
        const double packed[6] = {a[0], a[1], a[4], a[2], a[5], a[8]};
        std::copy(packed, packed + nc, out);
      } else {
        std::copy(a, a + nc, out);
      }
    }
    mesh.fields.push_back(std::move(f));
  }
  if (info)
    for (const auto& [type, count] : skipped) info->skipped_elements.emplace_back(type, count);
  return std::move(mesh);
}

void read_entities_41(GmshInput& in, GmshAssembler& out) {
  in.begin_data();
  std::uint64_t counts[4];
  for (std::uint64_t& c : counts) c = in.size("an entity count");
  for (int dim = 0; dim < 4; ++dim) {
    in.check_room(counts[dim], dim == 0 ? 36 : 68, dim == 0 ? 5 : 9, "entities");
    for (std::uint64_t i = 0; i < counts[dim]; ++i) {
      const int tag = in.int32("an entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) in.real("a bounding-box coordinate");
      const std::uint64_t num_physicals = in.size("a physical tag count");
      in.check_room(num_physicals, 4, 1, "physical tags");
      int ref = tag;
      for (std::uint64_t j = 0; j < num_physicals; ++j) {
        const int physical = in.int32("a physical tag");
        if (j == 0) ref = physical;
      }
      if (dim > 0) {
        const std::uint64_t num_bounding = in.size("a bounding entity count");
        in.check_room(num_bounding, 4, 1, "bounding entities");
        for (std::uint64_t j = 0; j < num_bounding; ++j) in.int32("a bounding entity tag");
      }
      out.entity_ref[{dim, tag}] = ref;
    }
  }
  in.end_data();
  in.expect_end("Entities");
}

void read_nodes_41(GmshInput& in, GmshAssembler& out) {
  in.begin_data();
  const std::uint64_t num_blocks = in.size("the number of node blocks");
  const std::uint64_t num_nodes = in.size("the number of nodes");
  in.size("the smallest node tag");
  in.size("the largest node tag");
  in.check_room(num_blocks, 20, 4, "node blocks");
  in.check_room(num_nodes, 32, 4, "nodes");
  if (num_nodes > kMaxIds) in.fail(std::to_string(num_nodes) + " nodes: too many for 32-bit ids");
  std::vector<std::uint64_t> tags;
  tags.reserve(static_cast<std::size_t>(num_nodes));
  std::vector<double>& coords = out.mesh.coords;
  coords.reserve(3 * static_cast<std::size_t>(num_nodes));
  for (std::uint64_t b = 0; b < num_blocks; ++b) {
    const int entity_dim = in.int32("an entity dimension");
    if (entity_dim < 0 || entity_dim > 3)
      in.fail("entity dimension " + std::to_string(entity_dim) + " (0 to 3 expected)");
    in.int32("an entity tag");
    const int parametric = in.int32("the parametric flag");
    if (parametric != 0 && parametric != 1)
      in.fail("parametric flag " + std::to_string(parametric) + " (0 or 1 expected)");
    const std::uint64_t n = in.size("the number of nodes of the block");
    if (n > num_nodes - tags.size())
      in.fail("the blocks hold more nodes than the " + std::to_string(num_nodes) + " announced");
    for (std::uint64_t i = 0; i < n; ++i) tags.push_back(in.size("a node tag"));
    const int extra = parametric ? entity_dim : 0;  // u, v, w after x, y, z
    for (std::uint64_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) coords.push_back(in.real("a coordinate"));
      for (int k = 0; k < extra; ++k) in.real("a parametric coordinate");
    }
  }
  if (tags.size() != num_nodes)
    in.fail("the blocks hold " + std::to_string(tags.size()) + " nodes, not the " +
            std::to_string(num_nodes) + " announced");
  out.end_nodes(tags, in);
}

void read_elements_41(GmshInput& in, GmshAssembler& out) {
  in.begin_data();
  const std::uint64_t num_blocks = in.size("the number of element blocks");
  const std::uint64_t num_elements = in.size("the number of elements");
  in.size("the smallest element tag");
  in.size("the largest element tag");
  in.check_room(num_blocks, 20, 4, "element blocks");
  in.check_room(num_elements, 16, 2, "elements");
  std::uint64_t seen = 0;
  for (std::uint64_t b = 0; b < num_blocks; ++b) {
    const int entity_dim = in.int32("an entity dimension");
    const int entity_tag = in.int32("an entity tag");
    const int type = in.int32("an element type");
    const std::uint64_t n = in.size("the number of elements of the block");
    if (n > num_elements - seen)
      in.fail("the blocks hold more elements than the " + std::to_string(num_elements) +
              " announced");
    seen += n;
    const int nv = nodes_per_element(type);
    if (nv == 0) in.fail("unknown element type " + std::to_string(type));
    in.check_room(n, 8 * static_cast<std::size_t>(1 + nv), static_cast<std::size_t>(1 + nv),
                  "elements");
    const bool kept = kept_type(type);
    if (!kept && type != kPoint && n > 0) in.fail(unsupported_elements(type, n));
    if (!kept) out.skipped[type] += static_cast<std::size_t>(n);
    if (kept && n > kMaxIds) in.fail("too many elements for 32-bit ids");
    const int ref = out.ref_of(entity_dim, entity_tag);
    Id v[4] = {};
    for (std::uint64_t e = 0; e < n; ++e) {
      in.size("an element tag");
      for (int k = 0; k < nv; ++k) {
        const std::uint64_t tag = in.size("a node tag");
        if (kept) v[k] = out.node(tag, in);
      }
      if (kept) out.add(type, v, ref);
    }
  }
  if (seen != num_elements)
    in.fail("the blocks hold " + std::to_string(seen) + " elements, not the " +
            std::to_string(num_elements) + " announced");
  in.end_data();
  in.expect_end("Elements");
}

namespace {

// $MeshFormat: returns the version (41 or 22) and switches `in` to binary if the file is.
int read_format(GmshInput& in, GmshReadInfo& info) {
  in.section = "$MeshFormat";
  std::string_view t;
  if (!in.next_token(t) || t != "$MeshFormat")
    in.fail("not a Gmsh .msh file ($MeshFormat expected first)");
  const std::string_view version = in.token("the format version");
  int v = 0;
  if (version == "4.1") {
    v = 41;
  } else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") {
    v = 22;
  } else if (version == "4" || version == "4.0") {
    in.fail("MSH 4.0 is not supported (re-save the file as MSH 4.1 or 2.2)");
  } else {
    in.fail("unknown MSH version " + medit_detail::quote(version) + " (4.1 or 2.2 expected)");
  }
  const int file_type = in.int32("the file type");
  if (file_type != 0 && file_type != 1)
    in.fail("file type " + std::to_string(file_type) + " (0 = ASCII or 1 = binary expected)");
  const int data_size = in.int32("the data size");
  if (data_size != 4 && data_size != 8)
    in.fail("data size " + std::to_string(data_size) + " (4 or 8 expected)");
  // (The room checks of binary 4.1 blocks count 8-byte size_t values: a valid file of a 32-bit
  // host was refused as truncated.)
  if (v == 41 && file_type == 1 && data_size == 4)
    in.fail(
        "binary MSH 4.1 with 4-byte sizes (a 32-bit host's) is not supported: re-save it "
        "as ASCII or on a 64-bit machine");
  info.version = v == 41 ? 4.1 : 2.2;
  info.binary = file_type == 1;
  if (info.binary) {
    // Binary 4.1: size_t values are data-size bytes; 2.2 only uses ints and doubles.
    in.set_binary(v == 41 ? data_size : 8, false);
    in.begin_data();
    const std::int32_t one = in.raw_int32();
    if (one != 1 && one != 0x01000000)
      in.fail("byte-order marker " + std::to_string(one) + " (1 expected)");
    in.set_binary(v == 41 ? data_size : 8, one != 1);
    in.end_data();
  }
  in.expect_end("MeshFormat");
  return v;
}

}  // namespace
}  // namespace gmsh_detail

Mesh read_gmsh_bytes(const std::string& name, std::string_view bytes,
                     const GmshReadOptions& options, GmshReadInfo* info) {
  using namespace gmsh_detail;
  GmshInput in(name, bytes);
  GmshAssembler out;
  GmshReadInfo local;
  GmshReadInfo& report = info ? *info : local;
  report = {};
  const int version = read_format(in, report);
  std::string_view t;
  while (in.next_token(t)) {
    in.section = std::string(t);
    if (t.size() < 2 || t[0] != '$' || t.substr(0, 4) == "$End")
      in.fail("expected a section name, got " + medit_detail::quote(t));
    const std::string_view name_of = t.substr(1);
    const bool need_nodes = name_of == "Elements" || name_of == "NodeData";
    if (need_nodes && !out.have_nodes) in.fail("section before $Nodes");
    if (name_of == "Nodes" && out.have_nodes) in.fail("second $Nodes section");
    if (name_of == "PartitionedEntities" && version == 41) {
      // Its elements sit on partition entities: read as such, they took the partitions' tags as
      // refs and the partition interfaces became boundary Edges.
      in.fail(
          "partitioned MSH 4.1 files are not supported: save the mesh unpartitioned "
          "(or as MSH 2.2)");
    } else if (name_of == "Entities" && version == 41) {
      read_entities_41(in, out);
    } else if (name_of == "Nodes") {
      version == 41 ? read_nodes_41(in, out) : read_nodes_22(in, out);
    } else if (name_of == "Elements") {
      version == 41 ? read_elements_41(in, out) : read_elements_22(in, out);
    } else if (name_of == "NodeData") {
      read_node_data(in, out);
    } else {
      in.skip_section(name_of);  // $PhysicalNames, $Periodic, $ElementData, ...
    }
  }
  return out.finish(options, info);
}

Mesh read_gmsh(const std::string& path, const GmshReadOptions& options, GmshReadInfo* info) {
  return read_gmsh_bytes(path, read_file_bytes(path), options, info);
}

}  // namespace riemesh
