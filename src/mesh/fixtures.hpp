#pragma once
// Meshes built in code, for tests and benchmarks (STYLE.md "Fixtures built in code").
#include "mesh/mesh.hpp"

namespace riemesh {

/// [0,1]² split into nx × ny cells, each cut into 2 counter-clockwise triangles along the
/// (0,0)-(1,1) diagonal. Vertex (i, j) has id j(nx+1) + i. Boundary Edges, oriented
/// counter-clockwise around the domain, have refs 1..4 = y=0, x=1, y=1, x=0; the 4 corners are
/// tagged kTagCorner. Triangle refs are 1. Counts: (nx+1)(ny+1) vertices, 2 nx ny triangles.
Mesh unit_square(int nx, int ny);

/// [0,1]³ split into n³ cubes, each cut into 6 positively oriented tetrahedra by the Kuhn
/// (Freudenthal) subdivision along the (0,0,0)-(1,1,1) diagonal, which is translation invariant
/// and hence conforming. Vertex (i, j, k) has id (k(n+1) + j)(n+1) + i. Boundary Triangles
/// (12 n², outward) have refs 1..6 = x=0, x=1, y=0, y=1, z=0, z=1; the 12 cube edges are Edges
/// tagged kTagRidge (refs 1..12, 12 n of them), the 8 corners are tagged kTagCorner, and ridge
/// vertices kTagRidge. Tet refs are 1.
Mesh unit_cube(int n);

/// unit_square(nx, ny) with every vertex off the square's boundary moved at random (seeded
/// std::mt19937, so the same on every machine) by up to `amount` cells per coordinate.
/// amount <= 0.2 keeps every triangle positive (a vertex and the line through the opposite edge
/// approach each other by at most 2 · 0.2√2 ≈ 0.57 cell, less than the 0.71 cell between them).
Mesh perturbed_unit_square(int nx, int ny, double amount, unsigned seed);

/// unit_cube(n) with its interior vertices moved the same way; amount <= 0.1 keeps the Kuhn
/// tetrahedra positive (2 · 0.1√3 ≈ 0.35 cell, less than the smallest height 1/√2 cell).
Mesh perturbed_unit_cube(int n, double amount, unsigned seed);

/// Unit icosphere: an icosahedron whose triangles are split into 4, `subdivisions` times, with
/// new vertices projected onto the sphere. 10·4^s + 2 vertices, 20·4^s triangles, oriented with
/// outward normals. Triangle refs are 1.
Mesh sphere_surface(int subdivisions);

}  // namespace riemesh
