// Malformed .msh input: one InputError line naming the file, the section and the line (ASCII)
// or byte offset (binary); truncated and corrupted binary files never crash or over-allocate.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/gmsh.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

// A valid 4.1 file: one triangle of ref 7 on surface 1 (lines numbered on the right).
const char kValid[] =
    "$MeshFormat\n"          // 1
    "4.1 0 8\n"              // 2
    "$EndMeshFormat\n"       // 3
    "$Entities\n"            // 4
    "0 0 1 0\n"              // 5
    "1 0 0 0 1 1 0 1 7 0\n"  // 6
    "$EndEntities\n"         // 7
    "$Nodes\n"               // 8
    "1 3 1 3\n"              // 9
    "2 1 0 3\n"              // 10
    "1\n2\n3\n"              // 11-13
    "0 0 0\n1 0 0\n0 1 0\n"  // 14-16
    "$EndNodes\n"            // 17
    "$Elements\n"            // 18
    "1 1 1 1\n"              // 19
    "2 1 2 1\n"              // 20
    "1 1 2 3\n"              // 21
    "$EndElements\n";        // 22

struct Edit {
  const char* from;  // replaced in kValid (first occurrence); null: the text is `to` alone
  const char* to;
  const char* message;  // expected start of the error after "<dir>/"
};

const Edit kBad[] = {
    {nullptr, "", "bad.msh:1: $MeshFormat: not a Gmsh .msh file ($MeshFormat expected first)"},
    {nullptr, "$NOD\n1\n", "bad.msh:1: $MeshFormat: not a Gmsh .msh file"},
    {"4.1 0 8", "4.0 0 8", "bad.msh:2: $MeshFormat: MSH 4.0 is not supported"},
    {"4.1 0 8", "3 0 8", "bad.msh:2: $MeshFormat: unknown MSH version '3' (4.1 or 2.2 expected)"},
    {"4.1 0 8", "4.1 2 8", "bad.msh:2: $MeshFormat: file type 2 (0 = ASCII or 1 = binary"},
    {"4.1 0 8", "4.1 0 16", "bad.msh:2: $MeshFormat: data size 16 (4 or 8 expected)"},
    {"4.1 0 8", "4.1 0", "bad.msh:3: $MeshFormat: expected the data size, got '$EndMeshFormat'"},
    {"0 0 1 0", "0 0 1000000000 0", "bad.msh:5: $Entities: 1000000000 entities cannot fit"},
    {"1 0 0 0 1 1 0 1 7 0", "1 0 0 0 1 1 0 1 7",
     "bad.msh:7: $Entities: expected a bounding entity count, got '$EndEntities'"},
    {"1 3 1 3", "1 1000000000 1 3", "bad.msh:9: $Nodes: 1000000000 nodes cannot fit"},
    {"1 3 1 3", "-1 3 1 3",
     "bad.msh:9: $Nodes: expected the number of node blocks (a "
     "non-negative integer), got '-1'"},
    {"2 1 0 3", "2 1 0 4", "bad.msh:10: $Nodes: the blocks hold more nodes than the 3 announced"},
    {"2 1 0 3", "4 1 0 3", "bad.msh:10: $Nodes: entity dimension 4 (0 to 3 expected)"},
    {"2 1 0 3", "2 1 2 3", "bad.msh:10: $Nodes: parametric flag 2 (0 or 1 expected)"},
    {"1\n2\n3\n", "1\n2\n2\n", "bad.msh:17: $Nodes: node tag 2 given twice"},
    {"1\n2\n3\n", "1\n0\n3\n", "bad.msh:17: $Nodes: node tag 0 (tags start at 1)"},
    {"1 0 0\n", "1 nan 0\n",
     "bad.msh:15: $Nodes: expected a coordinate (a finite real), got "
     "'nan'"},
    {"0 1 0\n$EndNodes", "0 1\n$EndNodes",
     "bad.msh:17: $Nodes: expected a coordinate, got "
     "'$EndNodes'"},
    {"0 1 0\n$EndNodes", "0 1 0 0\n$EndNodes", "bad.msh:16: $Nodes: expected $EndNodes, got '0'"},
    {"1 1 2 3\n", "1 1 2 9\n", "bad.msh:21: $Elements: unknown node tag 9"},
    {"2 1 2 1\n1 1 2 3\n", "2 1 3 1\n1 1 2 3 1\n",
     "bad.msh:20: $Elements: 1 element of type 3 (4-node quadrangle): riemesh reads 2-node "
     "lines, 3-node triangles and 4-node tetrahedra only"},
    {"4.1 0 8", "4.1 1 4", "bad.msh:2: $MeshFormat: binary MSH 4.1 with 4-byte sizes"},
    {"$Entities", "$PartitionedEntities\n0\n$EndPartitionedEntities\n$Entities",
     "bad.msh:4: $PartitionedEntities: partitioned MSH 4.1 files are not supported"},
    {"2 1 2 1\n", "2 1 99 1\n", "bad.msh:20: $Elements: unknown element type 99"},
    {"2 1 2 1\n", "2 1 2 5\n", "bad.msh:20: $Elements: the blocks hold more elements than the 1"},
    {"1 1 1 1\n", "1 2 1 1\n", "bad.msh:21: $Elements: the blocks hold 1 elements, not the 2"},
    {"1 1 2 3\n$EndElements\n", "1 1 2",
     "bad.msh:20: $Elements: 1 elements cannot fit in the 6 bytes left in the file"},
    {"1 1 2 3\n$EndElements\n", "1 1 2 # a long comment to make room",
     "bad.msh:21: $Elements: unexpected end of file, expected a node tag"},
    {"$EndElements\n", "",
     "bad.msh:21: $Elements: unexpected end of file, expected "
     "$EndElements"},
    {"$Nodes", "$Elements\n$EndElements\n$Nodes", "bad.msh:8: $Elements: section before $Nodes"},
    {"$Elements", "$Nodes\n0 0 0 0\n$EndNodes\n$Elements",
     "bad.msh:18: $Nodes: second $Nodes section"},
    {"$Entities", "$Foo\n1 2\n$EndFo\n$Entities", "bad.msh:4: $Foo: no $EndFoo before the end"},
    {"$Entities", "$EndFoo\n$Entities",
     "bad.msh:4: $EndFoo: expected a section name, got "
     "'$EndFoo'"},
    {"$EndElements\n", "$EndElements\n$NodeData\n1\n\"u\"\n0\n3\n0\n10\n1\n1 0 0\n",
     "bad.msh:30: $NodeData: field of 10 components (1 to 9 expected)"},
    {"$EndElements\n", "$EndElements\n$NodeData\n0\n0\n3\n0\n1\n2\n1 0\n7 0\n",
     "bad.msh:31: $NodeData: unknown node tag 7"},
    {"$EndElements\n", "$EndElements\n$NodeData\n0\n0\n2\n0\n1\n",
     "bad.msh:26: $NodeData: fewer than 3 integer tags"},
    {"$EndElements\n", "$EndElements\n$NodeData\n0\n0\n3\n0\n1\n99999999\n",
     "bad.msh:29: $NodeData: 99999999 values cannot fit"},
    // Version 2.2.
    {nullptr, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n",
     "bad.msh:5: $Nodes: 2 nodes cannot fit in the 9 bytes left in the file"},
    {nullptr, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 0 0\n",
     "bad.msh:7: $Nodes: unexpected end of file, expected a coordinate"},
    {nullptr, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n-1 0 0 0\n$EndNodes\n",
     "bad.msh:6: $Nodes: node tag -1 (tags start at 1)"},
    {nullptr,
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
     "$Elements\n1\n1 15 99 1\n$EndElements\n",
     "bad.msh:10: $Elements: element tag count 99 (0 to 64 expected)"},
    {nullptr,
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
     "$Elements\n1\n1 15 2 0 1 -4\n$EndElements\n",
     "bad.msh:10: $Elements: node tag -4 (tags start at 1)"},
    {nullptr,
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
     "$Elements\n1\n1 15 2 0 1 1\n$EndElements\n",
     nullptr},  // fine: one corner
    {nullptr,
     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
     "$Elements\n1\n1 9 2 0 1 1 1 1 1 1 1\n$EndElements\n",
     "bad.msh:10: $Elements: 1 element of type 9 (6-node triangle)"},
};

TEST(GmshErrors, AsciiTable) {
  test::ScratchDir dir;
  const std::string path = dir.file("bad.msh");
  const std::string prefix = dir.path().string() + "/";
  {
    test::write_text(path, kValid);
    const Mesh m = read_gmsh(path);
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.tri_ref, std::vector<std::int32_t>{7});
  }
  for (const Edit& bad : kBad) {
    std::string text = bad.to;
    if (bad.from) {
      text = kValid;
      const std::size_t at = text.find(bad.from);
      ASSERT_NE(at, std::string::npos) << bad.from;
      text.replace(at, std::string(bad.from).size(), bad.to);
    }
    SCOPED_TRACE(text);
    test::write_text(path, text);
    if (!bad.message) {
      EXPECT_NO_THROW(read_gmsh(path));
      continue;
    }
    try {
      read_gmsh(path);
      ADD_FAILURE() << "no error, expected " << bad.message;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(prefix + bad.message, 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(GmshErrors, MissingFileAndVersionInfo) {
  EXPECT_THROW(read_gmsh("/nonexistent/x.msh"), InputError);
}

// Every prefix of a binary file and every single-byte corruption either reads or throws
// InputError (never another exception, a crash or a huge allocation: run under ASan too).
TEST(GmshErrors, BinaryTruncationAndCorruptionSweeps) {
  Mesh m = test::cube_volume();
  m.fields.push_back({"u", FieldKind::kScalar, std::vector<double>(8, 0.5)});
  test::ScratchDir dir;
  GmshWriteOptions options;
  options.binary = true;
  write_gmsh(m, dir.file("c.msh"), options);
  const std::string bytes = test::read_text(dir.file("c.msh"));
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string_view cut = std::string_view(bytes).substr(0, n);
    try {
      read_gmsh_bytes("cut.msh", cut);
      // Only a file cut between sections (after an $End... line) is still valid.
      const std::size_t last = cut.rfind('$');
      ASSERT_NE(last, std::string_view::npos);
      EXPECT_EQ(cut.substr(last, 4), "$End") << n;
      EXPECT_EQ(cut.find_first_of(" \n", last), cut.find_first_of("\n", last)) << n;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.msh", 0), 0u);
    }
  }
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (unsigned char value : {0x00, 0x7f, 0xff}) {
      std::string bad = bytes;
      bad[i] = static_cast<char>(value);
      try {
        read_gmsh_bytes("bad.msh", bad);
      } catch (const InputError&) {
      }
    }
}

TEST(GmshErrors, BinaryErrorsNameByteOffsets) {
  test::ScratchDir dir;
  GmshWriteOptions options;
  options.binary = true;
  write_gmsh(test::cube_volume(), dir.file("c.msh"), options);
  std::string bytes = test::read_text(dir.file("c.msh"));
  // The node count (second size_t after "$Nodes\n") set to 2^40: cannot fit in the file.
  const std::size_t at = bytes.find("$Nodes\n") + 7 + 8;
  const std::uint64_t huge = std::uint64_t{1} << 40;
  std::memcpy(bytes.data() + at, &huge, 8);
  try {
    read_gmsh_bytes("c.msh", bytes);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("c.msh: byte " + std::to_string(at + 16) +
                                              ": $Nodes: 1099511627776 nodes cannot fit",
                                          0),
              0u)
        << e.what();
  }
  // A byte-order marker other than 1.
  bytes = test::read_text(dir.file("c.msh"));
  bytes[bytes.find("4.1 1 8\n") + 8] = 2;
  EXPECT_THROW(read_gmsh_bytes("c.msh", bytes), InputError);
}

}  // namespace
}  // namespace riemesh
