#include "io/sol.hpp"

#include <cmath>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medit_ascii_reader.hpp"
#include "io/medit_detail.hpp"
#include "io/meshb_stream.hpp"
#include "io/text_out.hpp"

namespace riemesh {

namespace {

using medit_detail::kSolAtVertices;

constexpr std::int64_t kMaxTypes = 1000;  // GmfMaxTyp in libmeshb7.h

struct SolSection {
  std::vector<FieldKind> kinds;
  int components = 0;  // per vertex, all fields
};

// Adds the fields of one SolAtVertices section to `fields` and fills them from next_real(),
// which yields the values in file order (interleaved per vertex).
template <class NextReal>
void fill_fields(const SolSection& section, std::size_t n, int file_dim, std::vector<Field>& fields,
                 NextReal next_real) {
  const std::size_t first = fields.size();
  for (FieldKind kind : section.kinds) {
    Field f;
    f.kind = kind;
    f.values.resize(n * field_components(kind, file_dim));
    fields.push_back(std::move(f));
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = first; k < fields.size(); ++k) {
      const std::size_t c = static_cast<std::size_t>(field_components(fields[k].kind, file_dim));
      for (std::size_t j = 0; j < c; ++j) fields[k].values[i * c + j] = next_real();
    }
  }
}

// Reads the #types and types of a SolAtVertices header through next_int(); fail(what) throws.
template <class NextInt, class Fail>
SolSection read_types(int file_dim, NextInt next_int, Fail fail) {
  const std::int64_t count = next_int();
  if (count < 1 || count > kMaxTypes) fail("bad number of solution types " + std::to_string(count));
  SolSection s;
  for (std::int64_t t = 0; t < count; ++t) {
    const std::int64_t type = next_int();
    if (type < 1 || type > 3)
      fail("unsupported solution type " + std::to_string(type) +
           " (1 scalar, 2 vector, 3 symmetric tensor)");
    s.kinds.push_back(static_cast<FieldKind>(type));
    s.components += field_components(s.kinds.back(), file_dim);
  }
  return s;
}

/// What a reader accepts: sections at `location` (or, while `any` holds, the first solution
/// section of any location, which then fixes it), with counts[location] entries.
struct Wanted {
  int mesh_dim = 0;  // the mesh's dimension (0: not known)
  bool any = false;
  SolLocation location = SolLocation::kVertices;
  std::size_t counts[3] = {0, 0, 0};
};

constexpr const char* kEntityNames[3] = {"vertices", "triangles", "tetrahedra"};

/// Why a section of these types cannot serve a mesh of mesh_dim, or "" (scalars serve any).
std::string dimension_mismatch(const SolSection& s, int file_dim, int mesh_dim) {
  if (mesh_dim == 0 || file_dim == mesh_dim) return "";
  for (const FieldKind k : s.kinds)
    if (k != FieldKind::kScalar)
      return "the file is in dimension " + std::to_string(file_dim) +
             " but the mesh in dimension " + std::to_string(mesh_dim);
  return "";
}

/// The location of a section code, or false for other keywords.
bool location_of(int code, SolLocation& at) {
  if (code == kSolAtVertices) at = SolLocation::kVertices;
  else if (code == medit_detail::kSolAtTriangles) at = SolLocation::kTriangles;
  else if (code == medit_detail::kSolAtTetrahedra) at = SolLocation::kTetrahedra;
  else return false;
  return true;
}

/// True if the section of this code is to be read (and fixes the location of an `any` request).
bool accept(int code, Wanted& w) {
  SolLocation at{};
  if (!location_of(code, at)) return false;
  if (w.any) {
    w.any = false;
    w.location = at;
  }
  return at == w.location;
}

std::string count_mismatch(std::size_t n, const Wanted& w) {
  const auto i = static_cast<std::size_t>(w.location);
  return std::to_string(n) + " values for a mesh of " + std::to_string(w.counts[i]) + " " +
         kEntityNames[i];
}

std::vector<Field> read_ascii(const std::string& path, std::string_view text, Wanted& w,
                              int& file_dim) {
  medit_detail::AsciiMeditReader in(path, text);
  std::vector<Field> fields;
  std::string_view kw;
  int code = 0;
  while (in.next_keyword(kw, code)) {
    if (!accept(code, w)) {
      in.skip_section(kw);
      continue;
    }
    file_dim = in.require_dim(kw);
    const std::size_t n = in.count(kw, 1);
    if (n != w.counts[static_cast<std::size_t>(w.location)]) in.fail_here(kw, count_mismatch(n, w));
    const SolSection s = read_types(
        file_dim, [&] { return in.integer(kw); },
        [&](const std::string& what) { in.fail_here(kw, what); });
    // Said before the values are read (a Dimension 3 tensor file for a planar mesh ran out of
    // numbers: "expected a real number, found 'End'").
    if (const std::string m = dimension_mismatch(s, file_dim, w.mesh_dim); !m.empty())
      in.fail_here(kw, m);
    in.check_room(kw, n, static_cast<std::size_t>(s.components));
    fill_fields(s, n, file_dim, fields, [&] { return in.real(kw); });
  }
  if (in.dim() == 0) medit_detail::fail(path, "Dimension", "missing (not a Medit solution file?)");
  file_dim = in.dim();
  return fields;
}

std::vector<Field> read_binary(const std::string& path, std::string_view bytes, Wanted& w,
                               int& file_dim) {
  medit_detail::MeshbReader in(path, bytes);
  std::vector<Field> fields;
  int code = 0;
  while (in.next_keyword(code)) {
    if (!accept(code, w)) {
      in.end_keyword(false);
      continue;
    }
    file_dim = in.require_dim();
    const std::size_t at = in.offset();
    const std::size_t n = in.count(0);
    if (n != w.counts[static_cast<std::size_t>(w.location)]) in.fail_at(at, count_mismatch(n, w));
    const SolSection s = read_types(
        file_dim, [&] { return std::int64_t{in.i32()}; },
        [&](const std::string& what) { in.fail_at(in.offset() - 4, what); });
    if (const std::string m = dimension_mismatch(s, file_dim, w.mesh_dim); !m.empty())
      in.fail_at(at, m);
    in.check_room(n, static_cast<std::size_t>(s.components) * in.real_size());
    fill_fields(s, n, file_dim, fields, [&] { return in.real(); });
    in.end_keyword(true);
  }
  if (in.dim() == 0) medit_detail::fail(path, "Dimension", "missing");
  file_dim = in.dim();
  return fields;
}

/// Reads the sections `w` asks for, checks dimensions and names the fields.
std::vector<Field> read_sections(const std::string& path, std::string_view bytes, Wanted& w,
                                 int dim) {
  medit_detail::check_sol_name(path);
  const bool binary = medit_detail::ends_with(path, ".solb");
  const bool any = w.any;
  w.mesh_dim = dim;
  int file_dim = 0;
  std::vector<Field> fields =
      binary ? read_binary(path, bytes, w, file_dim) : read_ascii(path, bytes, w, file_dim);
  if (fields.empty()) {
    if (any)
      medit_detail::fail(path, "", "no SolAtVertices, SolAtTriangles or SolAtTetrahedra section");
    medit_detail::fail(path, "SolAtVertices", "no solution at vertices in the file");
  }
  // (Tensors and vectors of another dimension than the mesh were refused section by section,
  // dimension_mismatch; scalars serve any dimension.)
  const bool metric = fields.size() == 1 && fields[0].kind == FieldKind::kSymTensor;
  for (std::size_t i = 0; i < fields.size(); ++i)
    fields[i].name = metric ? "metric" : "sol" + std::to_string(i);
  return fields;
}

}  // namespace

const char* sol_keyword(SolLocation location) {
  switch (location) {
    case SolLocation::kVertices:
      return "SolAtVertices";
    case SolLocation::kTriangles:
      return "SolAtTriangles";
    case SolLocation::kTetrahedra:
      return "SolAtTetrahedra";
  }
  return "SolAtVertices";
}

std::vector<Field> read_sol(const std::string& path, std::size_t num_vertices, int dim) {
  medit_detail::check_sol_name(path);
  return medit_detail::read_sol_bytes(path, read_file_bytes(path), num_vertices, dim);
}

std::vector<Field> read_sol(const std::string& path, const Mesh& mesh) {
  return read_sol(path, mesh.num_vertices(), mesh.dim);
}

SolData read_sol_any(const std::string& path, const Mesh& mesh) {
  medit_detail::check_sol_name(path);
  Wanted w;
  w.any = true;
  w.counts[0] = mesh.num_vertices();
  // A volume's Triangles are its boundary faces: SolAtTriangles of a volume counts those.
  w.counts[1] = mesh.num_triangles();
  w.counts[2] = mesh.num_tets();
  SolData out;
  out.fields = read_sections(path, read_file_bytes(path), w, mesh.dim);
  out.location = w.location;
  return out;
}

namespace medit_detail {

void check_sol_name(const std::string& path) {
  if (!ends_with(path, ".solb") && !ends_with(path, ".sol"))
    throw InputError(path + ": not a Medit solution file name (.sol or .solb expected)");
}

std::vector<Field> read_sol_bytes(const std::string& path, std::string_view bytes,
                                  std::size_t num_vertices, int dim) {
  Wanted w;
  w.counts[0] = num_vertices;
  return read_sections(path, bytes, w, dim);
}

}  // namespace medit_detail

namespace {

// Vertex count shared by all fields; throws Error if they disagree.
std::size_t checked_vertex_count(const std::vector<Field>& fields, int dim,
                                 const std::string& path) {
  auto bad = [&](const std::string& what) {
    throw Error(path + ": cannot write solution: " + what);
  };
  if (dim != 2 && dim != 3) bad("dimension " + std::to_string(dim));
  if (fields.empty()) bad("no field");
  std::size_t n = 0;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const int kind = static_cast<int>(fields[i].kind);
    if (kind < 1 || kind > 3) bad("unknown field kind " + std::to_string(kind));
    const std::size_t c = static_cast<std::size_t>(field_components(fields[i].kind, dim));
    if (fields[i].values.size() % c != 0) bad("field " + fields[i].name + " has a partial vertex");
    if (i == 0) n = fields[i].values.size() / c;
    if (fields[i].values.size() / c != n) bad("fields of different vertex counts");
    for (double x : fields[i].values)
      if (!std::isfinite(x)) bad("non-finite value in field " + fields[i].name);
  }
  return n;
}

int section_code(SolLocation location) {
  return location == SolLocation::kTriangles    ? medit_detail::kSolAtTriangles
         : location == SolLocation::kTetrahedra ? medit_detail::kSolAtTetrahedra
                                                : kSolAtVertices;
}

}  // namespace

void write_sol(const std::string& path, const std::vector<Field>& fields, int dim,
               const SolWriteOptions& options) {
  using medit_detail::ends_with;
  const bool binary = ends_with(path, ".solb");
  if (!binary && !ends_with(path, ".sol"))
    throw InputError(path + ": not a Medit solution file name (.sol or .solb expected)");
  const std::size_t n = checked_vertex_count(fields, dim, path);
  std::vector<std::size_t> comps;
  std::uint64_t per_vertex = 0;
  for (const Field& f : fields) {
    comps.push_back(static_cast<std::size_t>(field_components(f.kind, dim)));
    per_vertex += comps.back();
  }
  AtomicFile file(path, options.sync);
  if (binary) {
    const std::uint64_t estimate = 1024 + n * per_vertex * 8;
    const int version =
        medit_detail::choose_meshb_version(options.binary_version, estimate, n, path);
    medit_detail::MeshbWriter out(version, dim, estimate);
    out.keyword(section_code(options.location), static_cast<std::int64_t>(n));
    out.i32(static_cast<std::int32_t>(fields.size()));
    for (const Field& f : fields) out.i32(static_cast<std::int32_t>(f.kind));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < fields.size(); ++k)
        for (std::size_t j = 0; j < comps[k]; ++j) out.real(fields[k].values[i * comps[k] + j]);
    file.write(out.finish());
  } else {
    io_detail::TextOut out(file);
    out.text("MeshVersionFormatted 2\n\nDimension ").integer(dim).text("\n\n");
    out.text(sol_keyword(options.location)).text("\n");
    out.integer(static_cast<std::int64_t>(n))
        .text("\n")
        .integer(static_cast<std::int64_t>(fields.size()));
    for (const Field& f : fields) out.text(" ").integer(static_cast<int>(f.kind));
    out.text("\n");
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < fields.size(); ++k)
        for (std::size_t j = 0; j < comps[k]; ++j)
          out.real(fields[k].values[i * comps[k] + j])
              .text(k + 1 == fields.size() && j + 1 == comps[k] ? "\n" : " ");
    }
    out.text("\nEnd\n");
    out.flush();
  }
  file.commit();
}

}  // namespace riemesh
