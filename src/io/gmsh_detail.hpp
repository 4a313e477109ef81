#pragma once
// Internals of the Gmsh reader: one input class that reads the same sections from ASCII tokens
// or binary values (MSH 4.1 lists the same numbers in the same order in both encodings), the
// node-tag map, and the assembler that turns elements into a Mesh.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/byte_order.hpp"
#include "io/gmsh.hpp"
#include "io/text_scanner.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::gmsh_detail {

// Gmsh element types Riemesh keeps.
constexpr int kLine = 1, kTriangle = 2, kTetrahedron = 4, kPoint = 15;

/// Nodes of an element of Gmsh type `type` (gmsh.info "MSH file format", elm-type); 0 if the
/// type is unknown.
int nodes_per_element(int type);

/// "N elements of type T (name): riemesh reads ... only": elements other than lines, triangles,
/// tetrahedra and points are refused (they were dropped without a word).
std::string unsupported_elements(int type, std::uint64_t count);

/// The bytes of a .msh file read as text tokens (section names, ASCII data, headers) or as
/// binary values. Every failure throws InputError("<file>:<line>: $<Section>: <what>"), with a
/// byte offset instead of the line for binary data.
class GmshInput {
 public:
  GmshInput(std::string name, std::string_view bytes);

  /// Next text token; false at the end of the file.
  bool next_token(std::string_view& token);
  /// Next text token; fails at the end of the file.
  std::string_view token(const char* what);

  /// Switches the value readers to binary once $MeshFormat said so: `size_bytes` is the width
  /// of size_t values, `swap` whether the file's byte order is the reverse of ours.
  void set_binary(int size_bytes, bool swap);
  bool binary() const { return binary_; }
  /// Binary data starts after the end of the current line (no-op in ASCII).
  void begin_data();
  /// Text scanning resumes after the binary data (no-op in ASCII).
  void end_data();

  /// An `int` value (4 bytes in binary), within the int32 range.
  std::int32_t int32(const char* what);
  /// A `size_t` value (data-size bytes in binary), non-negative.
  std::uint64_t size(const char* what);
  /// A finite `double` value.
  double real(const char* what);
  /// The raw binary int32 that $MeshFormat holds to tell the byte order.
  std::int32_t raw_int32();

  /// Fails unless n entries fit in the rest of the file, an entry taking at least
  /// `binary_bytes` bytes in binary and `ascii_tokens` tokens in ASCII. Guards every allocation
  /// sized by a count read from the file.
  void check_room(std::uint64_t n, std::size_t binary_bytes, std::size_t ascii_tokens,
                  const char* what);
  /// Skips to just after "$End<name>".
  void skip_section(std::string_view name);
  /// The next token must be "$End<name>".
  void expect_end(std::string_view name);

  /// "<file>:<line>" (ASCII) or "<file>: byte <offset>" (binary) of the last thing read.
  std::string where() const;
  [[noreturn]] void fail(const std::string& what) const;

  /// The section being read ("$Nodes"), for messages.
  std::string section;

 private:
  void need(std::size_t bytes, const char* what);
  template <class T>
  T raw() {
    const T value = io_detail::load_value<T>(bytes_.data() + pos_, swap_);
    pos_ += sizeof(T);
    return value;
  }
  std::string_view value_token(const char* what);

  std::string name_;
  std::string_view bytes_;
  io_detail::TextScanner scanner_;
  bool binary_ = false;
  bool swap_ = false;
  bool in_data_ = false;
  int size_bytes_ = 8;
  std::size_t pos_ = 0;       // binary read position
  std::size_t last_pos_ = 0;  // byte offset of the last value or token read
};

/// Node tags (possibly sparse and unordered) to 0-based ids in order of appearance.
class NodeMap {
 public:
  /// Builds the map; fails through `input` on a duplicate or zero tag.
  void build(const std::vector<std::uint64_t>& tags, const GmshInput& input);
  /// The id of a node tag, or kNoId.
  Id find(std::uint64_t tag) const;

 private:
  std::vector<Id> dense_;                             // by tag, when tags are compact
  std::vector<std::pair<std::uint64_t, Id>> sparse_;  // sorted by tag otherwise
};

/// A $NodeData view as read: `components` values per node (1, 3 or 9), 0 where not given.
struct RawField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// Collects what the section readers parse and turns it into a Mesh.
struct GmshAssembler {
  Mesh mesh;  // dim 3 while reading
  NodeMap nodes;
  bool have_nodes = false;
  /// Physical-or-elementary ref of each entity (dim, tag) listed in $Entities.
  std::map<std::pair<int, int>, int> entity_ref;
  std::vector<Id> corners;
  std::map<int, std::size_t> skipped;  // element type -> count
  std::vector<RawField> fields;

  /// The ref of elements of entity (dim, tag): its first physical tag, else its tag.
  int ref_of(int dim, int tag) const;
  /// Node ids of an element read from node tags; fails through `input` on an unknown tag.
  Id node(std::uint64_t tag, const GmshInput& input) const;
  /// Adds an element of a kept type (kPoint, kLine, kTriangle, kTetrahedron).
  void add(int type, const Id* v, int ref);
  /// Closes a $Nodes section (both versions): the node tags, in file order, become vertex ids.
  void end_nodes(const std::vector<std::uint64_t>& tags, GmshInput& input);
  Mesh finish(const GmshReadOptions& options, GmshReadInfo* info);
};

// Section readers. The input is just after the section name; each reads through $End<name>.
void read_entities_41(GmshInput& in, GmshAssembler& out);
void read_nodes_41(GmshInput& in, GmshAssembler& out);
void read_elements_41(GmshInput& in, GmshAssembler& out);
void read_nodes_22(GmshInput& in, GmshAssembler& out);
void read_elements_22(GmshInput& in, GmshAssembler& out);
void read_node_data(GmshInput& in, GmshAssembler& out);

}  // namespace riemesh::gmsh_detail
