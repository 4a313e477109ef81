// Reading MSH 2.2 $Nodes and $Elements (ASCII and binary) and $NodeData (2.2 and 4.1 alike).
#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "io/gmsh_detail.hpp"
#include "io/medit_detail.hpp"

namespace riemesh::gmsh_detail {

namespace {

// A 2.2 node tag (an int) as a tag for NodeMap: non-positive tags become 0, which no node has.
std::uint64_t node_tag(std::int32_t tag) { return tag > 0 ? static_cast<std::uint64_t>(tag) : 0; }

/// The element read last: MSH 2.2 writes an element once per physical group of its entity, one
/// copy after the other (with another physical tag); the copies are one element, as in 4.1.
struct LastElement {
  int type = -1;
  std::int32_t entity = 0;
  std::int32_t nodes[4] = {};
};

// One 2.2 element once its type and tags are known: node tags, then the element if kept.
void read_element_nodes(GmshInput& in, GmshAssembler& out, int type, int nv, int ref,
                        std::int32_t entity, LastElement& last) {
  const bool kept = type == kPoint || type == kLine || type == kTriangle || type == kTetrahedron;
  Id v[4] = {};
  std::int32_t tags[4] = {};
  for (int k = 0; k < nv; ++k) {
    const std::int32_t tag = in.int32("a node tag");
    if (tag <= 0) in.fail("node tag " + std::to_string(tag) + " (tags start at 1)");
    if (kept) v[k] = out.node(node_tag(tag), in), tags[k] = tag;
  }
  if (kept) {
    const bool copy =
        type == last.type && entity == last.entity && std::equal(tags, tags + nv, last.nodes);
    if (copy) return;
    last.type = type, last.entity = entity;
    std::copy(tags, tags + nv, last.nodes);
    out.add(type, v, ref);
  } else {
    in.fail(unsupported_elements(type, 1));  // (points are kept: kPoint above)
  }
}

// 2.2 tags: physical, elementary, ...; physical 0 means none: the elementary tag is the ref.
int ref_of_tags(const std::int32_t* tags, std::int32_t num_tags) {
  if (num_tags >= 1 && tags[0] != 0) return tags[0];
  return num_tags >= 2 ? tags[1] : 0;
}

void check_type(GmshInput& in, int type, int& nv) {
  nv = nodes_per_element(type);
  if (nv == 0) in.fail("unknown element type " + std::to_string(type));
}

}  // namespace

void read_nodes_22(GmshInput& in, GmshAssembler& out) {
  const std::uint64_t n = in.size("the number of nodes");
  in.begin_data();
  in.check_room(n, 28, 4, "nodes");
  if (n > static_cast<std::uint64_t>(std::numeric_limits<Id>::max()))
    in.fail(std::to_string(n) + " nodes: too many for 32-bit ids");
  std::vector<std::uint64_t> tags(static_cast<std::size_t>(n));
  std::vector<double>& coords = out.mesh.coords;
  coords.resize(3 * tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const std::int32_t tag = in.int32("a node tag");
    if (tag <= 0) in.fail("node tag " + std::to_string(tag) + " (tags start at 1)");
    tags[i] = static_cast<std::uint64_t>(tag);
    for (int k = 0; k < 3; ++k) coords[3 * i + k] = in.real("a coordinate");
  }
  out.end_nodes(tags, in);
}

void read_elements_22(GmshInput& in, GmshAssembler& out) {
  const std::uint64_t n = in.size("the number of elements");
  in.begin_data();
  in.check_room(n, 12, 5, "elements");
  std::int32_t tags[64];
  LastElement last;
  // 2.2 tags: physical, elementary, ...
  auto entity_of = [&](std::int32_t num_tags) { return num_tags >= 2 ? tags[1] : 0; };
  auto read_tags = [&](std::int32_t num_tags) {
    if (num_tags < 0 || num_tags > 64)
      in.fail("element tag count " + std::to_string(num_tags) + " (0 to 64 expected)");
    for (std::int32_t j = 0; j < num_tags; ++j) tags[j] = in.int32("an element tag");
  };
  if (!in.binary()) {
    // elm-number elm-type number-of-tags tag... node...
    for (std::uint64_t e = 0; e < n; ++e) {
      in.int32("an element number");
      const int type = in.int32("an element type");
      int nv = 0;
      check_type(in, type, nv);
      const std::int32_t num_tags = in.int32("the number of tags");
      read_tags(num_tags);
      read_element_nodes(in, out, type, nv, ref_of_tags(tags, num_tags), entity_of(num_tags), last);
    }
  } else {
    // Blocks: elm-type num-elm-follow num-tags, then per element: number, tags, nodes.
    std::uint64_t seen = 0;
    while (seen < n) {
      const int type = in.int32("an element type");
      int nv = 0;
      check_type(in, type, nv);
      const std::int32_t follow = in.int32("the number of elements that follow");
      if (follow <= 0 || static_cast<std::uint64_t>(follow) > n - seen)
        in.fail("block of " + std::to_string(follow) + " elements (1 to " +
                std::to_string(n - seen) + " expected)");
      const std::int32_t num_tags = in.int32("the number of tags");
      if (num_tags < 0 || num_tags > 64)
        in.fail("element tag count " + std::to_string(num_tags) + " (0 to 64 expected)");
      in.check_room(static_cast<std::uint64_t>(follow),
                    4 * static_cast<std::size_t>(1 + num_tags + nv), 0, "elements");
      for (std::int32_t e = 0; e < follow; ++e) {
        in.int32("an element number");
        read_tags(num_tags);
        read_element_nodes(in, out, type, nv, ref_of_tags(tags, num_tags), entity_of(num_tags),
                           last);
      }
      seen += static_cast<std::uint64_t>(follow);
    }
  }
  in.end_data();
  in.expect_end("Elements");
}

void read_node_data(GmshInput& in, GmshAssembler& out) {
  RawField field;
  field.name = "field" + std::to_string(out.fields.size());
  const std::int32_t num_strings = in.int32("the number of string tags");
  if (num_strings < 0) in.fail("negative string tag count");
  in.check_room(static_cast<std::uint64_t>(num_strings), 0, 1, "string tags");
  for (std::int32_t i = 0; i < num_strings; ++i) {
    std::string_view s = in.token("a string tag");
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
    if (i == 0) field.name = std::string(s);
  }
  const std::int32_t num_reals = in.int32("the number of real tags");
  if (num_reals < 0) in.fail("negative real tag count");
  in.check_room(static_cast<std::uint64_t>(num_reals), 0, 1, "real tags");
  for (std::int32_t i = 0; i < num_reals; ++i) in.real("a real tag");
  const std::int32_t num_ints = in.int32("the number of integer tags");
  if (num_ints < 3) in.fail("fewer than 3 integer tags (time step, components, count)");
  in.check_room(static_cast<std::uint64_t>(num_ints), 0, 1, "integer tags");
  std::int32_t ints[3] = {};
  for (std::int32_t i = 0; i < num_ints; ++i) {
    const std::int32_t v = in.int32("an integer tag");
    if (i < 3) ints[i] = v;
  }
  const int components = ints[1];
  if (components < 1 || components > 9)
    in.fail("field of " + std::to_string(components) + " components (1 to 9 expected)");
  if (ints[2] < 0) in.fail("negative value count " + std::to_string(ints[2]));
  const auto count = static_cast<std::uint64_t>(ints[2]);
  field.components = components;
  const bool keep = components == 1 || components == 3 || components == 9;
  const std::size_t nv = out.mesh.num_vertices();
  if (keep) field.values.assign(nv * static_cast<std::size_t>(components), 0.0);
  in.begin_data();
  in.check_room(count, 4 + 8 * static_cast<std::size_t>(components),
                1 + static_cast<std::size_t>(components), "values");
  for (std::uint64_t i = 0; i < count; ++i) {
    const Id v = out.node(node_tag(in.int32("a node tag")), in);
    for (int k = 0; k < components; ++k) {
      const double x = in.real("a field value");
      if (keep) field.values[static_cast<std::size_t>(v) * components + k] = x;
    }
  }
  in.end_data();
  in.expect_end("NodeData");
  if (!keep) return;
  // A later view of the same name (a later time step) replaces the earlier one.
  auto same = std::find_if(out.fields.begin(), out.fields.end(),
                           [&](const RawField& f) { return f.name == field.name; });
  if (same != out.fields.end())
    *same = std::move(field);
  else
    out.fields.push_back(std::move(field));
}

}  // namespace riemesh::gmsh_detail
