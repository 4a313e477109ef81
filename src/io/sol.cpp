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

std::string vertex_mismatch(std::size_t n, std::size_t num_vertices) {
  return std::to_string(n) + " values for a mesh of " + std::to_string(num_vertices) + " vertices";
}

std::vector<Field> read_ascii(const std::string& path, std::string_view text,
                              std::size_t num_vertices, int& file_dim) {
  medit_detail::AsciiMeditReader in(path, text);
  std::vector<Field> fields;
  std::string_view kw;
  int code = 0;
  while (in.next_keyword(kw, code)) {
    if (code != kSolAtVertices) {
      in.skip_section(kw);
      continue;
    }
    file_dim = in.require_dim(kw);
    const std::size_t n = in.count(kw, 1);
    if (n != num_vertices) in.fail_here(kw, vertex_mismatch(n, num_vertices));
    const SolSection s = read_types(
        file_dim, [&] { return in.integer(kw); },
        [&](const std::string& what) { in.fail_here(kw, what); });
    in.check_room(kw, n, static_cast<std::size_t>(s.components));
    fill_fields(s, n, file_dim, fields, [&] { return in.real(kw); });
  }
  if (in.dim() == 0) medit_detail::fail(path, "Dimension", "missing (not a Medit solution file?)");
  file_dim = in.dim();
  return fields;
}

std::vector<Field> read_binary(const std::string& path, std::string_view bytes,
                               std::size_t num_vertices, int& file_dim) {
  medit_detail::MeshbReader in(path, bytes);
  std::vector<Field> fields;
  int code = 0;
  while (in.next_keyword(code)) {
    if (code != kSolAtVertices) {
      in.end_keyword(false);
      continue;
    }
    file_dim = in.require_dim();
    const std::size_t at = in.offset();
    const std::size_t n = in.count(0);
    if (n != num_vertices) in.fail_at(at, vertex_mismatch(n, num_vertices));
    const SolSection s = read_types(
        file_dim, [&] { return std::int64_t{in.i32()}; },
        [&](const std::string& what) { in.fail_at(in.offset() - 4, what); });
    in.check_room(n, static_cast<std::size_t>(s.components) * in.real_size());
    fill_fields(s, n, file_dim, fields, [&] { return in.real(); });
    in.end_keyword(true);
  }
  if (in.dim() == 0) medit_detail::fail(path, "Dimension", "missing");
  file_dim = in.dim();
  return fields;
}

}  // namespace

std::vector<Field> read_sol(const std::string& path, std::size_t num_vertices, int dim) {
  medit_detail::check_sol_name(path);
  return medit_detail::read_sol_bytes(path, read_file_bytes(path), num_vertices, dim);
}

std::vector<Field> read_sol(const std::string& path, const Mesh& mesh) {
  return read_sol(path, mesh.num_vertices(), mesh.dim);
}

namespace medit_detail {

void check_sol_name(const std::string& path) {
  if (!ends_with(path, ".solb") && !ends_with(path, ".sol"))
    throw InputError(path + ": not a Medit solution file name (.sol or .solb expected)");
}

std::vector<Field> read_sol_bytes(const std::string& path, std::string_view bytes,
                                  std::size_t num_vertices, int dim) {
  check_sol_name(path);
  const bool binary = ends_with(path, ".solb");
  int file_dim = 0;
  std::vector<Field> fields = binary ? read_binary(path, bytes, num_vertices, file_dim)
                                     : read_ascii(path, bytes, num_vertices, file_dim);
  if (fields.empty())
    medit_detail::fail(path, "SolAtVertices", "no solution at vertices in the file");
  for (const Field& f : fields) {
    // Scalars do not depend on the dimension: a Dimension 3 .sol of a planar mesh is usable.
    if (f.kind != FieldKind::kScalar && file_dim != dim)
      medit_detail::fail(path, "Dimension",
                         "the file is in dimension " + std::to_string(file_dim) +
                             " but the mesh in dimension " + std::to_string(dim));
  }
  const bool metric = fields.size() == 1 && fields[0].kind == FieldKind::kSymTensor;
  for (std::size_t i = 0; i < fields.size(); ++i)
    fields[i].name = metric ? "metric" : "sol" + std::to_string(i);
  return fields;
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
    out.keyword(kSolAtVertices, static_cast<std::int64_t>(n));
    out.i32(static_cast<std::int32_t>(fields.size()));
    for (const Field& f : fields) out.i32(static_cast<std::int32_t>(f.kind));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < fields.size(); ++k)
        for (std::size_t j = 0; j < comps[k]; ++j) out.real(fields[k].values[i * comps[k] + j]);
    file.write(out.finish());
  } else {
    io_detail::TextOut out(file);
    out.text("MeshVersionFormatted 2\n\nDimension ").integer(dim).text("\n\nSolAtVertices\n");
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
