#pragma once
// Planar geometries in Gmsh's .geo language (a subset): the description `riemesh mesh IN.geo`
// meshes (issue #8: parametric curves from a small geometry description). What is read:
//
//   // comments, /* block comments */
//   lc = 0.1;  r = 2 * lc + Sqrt(2);              variables: numbers, + - * / ^, ( ), Pi,
//                                                 Sqrt Sin Cos Tan Asin Acos Atan Atan2 Exp Log
//                                                 Fabs Hypot Min Max Floor Ceil
//   Point(1) = {x, y, z, lc};                     z must be 0; lc (size at the point) optional
//   Line(1) = {1, 2};                             the segment from point 1 to point 2
//   Circle(2) = {2, 3, 4};                        arc from point 2 to point 4 centred at point 3
//                                                 (the shorter way; a half circle
//                                                 counter-clockwise, as in Gmsh)
//   Spline(3) = {4, 5, 6, 7};                     cubic (Catmull-Rom) through the points; first
//                                                 = last: a closed curve
//   Curve Loop(1) = {1, 2, -3};   Line Loop(1) = ...   curves chained; -c: curve c reversed
//   Plane Surface(1) = {1, 2};                    outer loop, then holes
//   Physical Curve(10) = {1, 2};  Physical Line("wall", 10) = {...};   edge refs
//   Physical Surface(1) = {1};                    triangle refs
//   Mesh.Algorithm = 6;  (options Mesh.*, Geometry.*, General.*)      ignored, listed in `ignored`
//
// Lists take expressions and ranges a:b (step 1) or a:b:s. Anything else (Extrude, Transfinite,
// Ellipse, BSpline, For, If, Field, ...) is an error naming it. Every entity keeps the line it was
// defined on, for the errors of later stages.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace riemesh {

struct GeoPoint {
  int id = 0;
  double x = 0.0, y = 0.0;
  double lc = 0.0;  ///< size at the point; 0 when not given
  std::size_t line = 0;
};

enum class GeoCurveKind { kLine, kCircle, kSpline };

struct GeoCurve {
  int id = 0;
  GeoCurveKind kind = GeoCurveKind::kLine;
  /// Point ids: Line {start, end}; Circle {start, centre, end}; Spline {p0, ..., pn} (n >= 1).
  std::vector<int> points;
  std::size_t line = 0;
};

/// A Curve Loop (or Line Loop): curve ids, negative for a curve taken from its end to its start.
struct GeoLoop {
  int id = 0;
  std::vector<int> curves;
  std::size_t line = 0;
};

/// A Plane Surface: loop ids, the first its outer boundary, the others holes in it.
struct GeoSurface {
  int id = 0;
  std::vector<int> loops;
  std::size_t line = 0;
};

/// A Physical Curve (Physical Line) or Physical Surface: tag, optional name, entity ids.
struct GeoPhysical {
  int tag = 0;
  std::string name;
  std::vector<int> ids;
  std::size_t line = 0;
};

struct Geometry2d {
  std::vector<GeoPoint> points;  ///< in the order of the file
  std::vector<GeoCurve> curves;
  std::vector<GeoLoop> loops;
  std::vector<GeoSurface> surfaces;
  std::vector<GeoPhysical> physical_curves, physical_surfaces;
  std::vector<std::string> ignored;  ///< "line N: Mesh.Algorithm" for each option ignored
};

/// Parses .geo text. Checks: ids unique per kind and positive; every id referenced defined before
/// use (points of curves, curves of loops — sign aside —, loops of surfaces, entities of physical
/// groups); Line: 2 distinct points; Circle: 3 points, start and end at the same distance from the
/// centre (1e-6 relative); Spline: >= 2 points; z = 0.
/// Throws InputError "line N: message" on the first error.
Geometry2d parse_geo(std::string_view text);

/// Reads a .geo file: parse_geo with errors as "PATH:N: message" (and "PATH: cannot open").
Geometry2d read_geo(const std::string& path);

/// An error message of a stage reading the geometry of file `path`: "line N: text" becomes
/// "PATH:N: text", any other message "PATH: message".
std::string geo_message(const std::string& path, std::string_view message);

}  // namespace riemesh
