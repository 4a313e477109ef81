// The .geo reader (io/geo.hpp): the subset of Gmsh's language it reads, the values and lines it
// keeps, and one error line per malformed input, with the line of the fault.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "external_tools.hpp"
#include "io/geo.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

const std::string kSquareHole = std::string(RIEMESH_TEST_DIR) + "/data/geo/square_hole.geo";

/// The message of the InputError parse_geo throws, or "no error".
std::string error_of(const std::string& text) {
  try {
    parse_geo(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// The value of an expression, read through the x of a point.
double eval(const std::string& expression, const std::string& before = "") {
  const Geometry2d g = parse_geo(before + "Point(1) = {" + expression + ", 0, 0};");
  return g.points.at(0).x;
}

std::vector<int> ids_of(const std::string& list, const std::string& before) {
  return parse_geo(before + "Physical Curve(1) = {" + list + "};").physical_curves.at(0).ids;
}

// Unit square, points 1-4 counter-clockwise, lines 1-4 along its sides (lines 1-4 of the text).
const char kSquare[] =
    "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4};\n"
    "Plane Surface(1) = {1};\n";

TEST(Geo, SquareWithVariablesAndSizes) {
  const Geometry2d g = parse_geo(
      "lc = 0.1;\n"
      "L = 2 * lc * 5;  // 1\n"
      "Point(1) = {0, 0, 0, lc};\n"
      "Point(2) = {L, 0, 0, lc};\n"
      "Point(3) = {L, L, 0};\n"
      "Point(4) = {0, L, 0, lc / 2};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3};\n"
      "Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Curve Loop(1) = {1, 2, 3, 4};\n"
      "Plane Surface(1) = {1};\n");
  ASSERT_EQ(g.points.size(), 4u);
  EXPECT_EQ(g.points[1].id, 2);
  EXPECT_DOUBLE_EQ(g.points[1].x, 1.0);
  EXPECT_DOUBLE_EQ(g.points[1].y, 0.0);
  EXPECT_DOUBLE_EQ(g.points[1].lc, 0.1);
  EXPECT_DOUBLE_EQ(g.points[2].y, 1.0);
  EXPECT_EQ(g.points[2].lc, 0.0);  // not given
  EXPECT_DOUBLE_EQ(g.points[3].lc, 0.05);
  EXPECT_EQ(g.points[0].line, 3u);
  EXPECT_EQ(g.points[3].line, 6u);
  ASSERT_EQ(g.curves.size(), 4u);
  for (const GeoCurve& c : g.curves) EXPECT_EQ(c.kind, GeoCurveKind::kLine);
  EXPECT_EQ(g.curves[3].points, (std::vector<int>{4, 1}));
  EXPECT_EQ(g.curves[1].line, 7u);
  EXPECT_EQ(g.curves[2].line, 8u);
  ASSERT_EQ(g.loops.size(), 1u);
  EXPECT_EQ(g.loops[0].curves, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(g.loops[0].line, 9u);
  ASSERT_EQ(g.surfaces.size(), 1u);
  EXPECT_EQ(g.surfaces[0].id, 1);
  EXPECT_EQ(g.surfaces[0].loops, (std::vector<int>{1}));
  EXPECT_EQ(g.surfaces[0].line, 10u);
  EXPECT_TRUE(g.physical_curves.empty());
  EXPECT_TRUE(g.ignored.empty());
}

TEST(Geo, CircleOfFourArcs) {
  const Geometry2d g = parse_geo(
      "r = 2;\n"
      "Point(1) = {0, 0, 0};\n"
      "For_ = 0;  // a variable, not the For keyword\n"
      "Point(2) = {r * Cos(0 * Pi / 2), r * Sin(0 * Pi / 2), 0};\n"
      "Point(3) = {r * Cos(1 * Pi / 2), r * Sin(1 * Pi / 2), 0};\n"
      "Point(4) = {r * Cos(2 * Pi / 2), r * Sin(2 * Pi / 2), 0};\n"
      "Point(5) = {r * Cos(3 * Pi / 2), r * Sin(3 * Pi / 2), 0};\n"
      "Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, "
      "2};\n"
      "Curve Loop(1) = {1:4};\n"
      "Plane Surface(1) = {1};\n");
  ASSERT_EQ(g.curves.size(), 4u);
  for (const GeoCurve& c : g.curves) {
    EXPECT_EQ(c.kind, GeoCurveKind::kCircle);
    EXPECT_EQ(c.points[1], 1);
    EXPECT_EQ(c.line, 8u);
  }
  EXPECT_EQ(g.curves[3].points, (std::vector<int>{5, 1, 2}));
  EXPECT_NEAR(g.points[3].x, -2.0, 1e-15);
  EXPECT_NEAR(g.points[4].y, -2.0, 1e-15);
  EXPECT_EQ(g.loops[0].curves, (std::vector<int>{1, 2, 3, 4}));
}

TEST(Geo, HalfCirclesAsInGmsh) {
  // Start and end opposite across the centre: Gmsh takes the arc counter-clockwise, and two such
  // arcs make a circle (tests/data/geo/square_hole.geo relies on it).
  const Geometry2d g = parse_geo(
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {-1, 0, 0};\n"
      "Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 2};\n"
      "Curve Loop(1) = {1, 2};\n");
  EXPECT_EQ(g.curves.size(), 2u);
}

TEST(Geo, ClosedSpline) {
  const Geometry2d g = parse_geo(
      "Point(1) = {1, 0, 0}; Point(2) = {0, 1, 0}; Point(3) = {-1, 0, 0}; Point(4) = {0, -1, 0};\n"
      "Spline(7) = {1, 2, 3, 4, 1};\n"
      "Curve Loop(1) = {7};\n"
      "Plane Surface(1) = {1};\n"
      "Spline(8) = {1, 3};  // two points: a segment\n");
  ASSERT_EQ(g.curves.size(), 2u);
  EXPECT_EQ(g.curves[0].id, 7);
  EXPECT_EQ(g.curves[0].kind, GeoCurveKind::kSpline);
  EXPECT_EQ(g.curves[0].points, (std::vector<int>{1, 2, 3, 4, 1}));
  EXPECT_EQ(g.curves[0].points.front(), g.curves[0].points.back());
  EXPECT_EQ(g.curves[1].points, (std::vector<int>{1, 3}));
  EXPECT_EQ(g.loops[0].curves, (std::vector<int>{7}));
}

TEST(Geo, LoopsWithReversedCurves) {
  const Geometry2d g = parse_geo(
      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {1, 4};\n"
      "Line Loop(1) = {1, 2, -3, -4};\n"
      "Curve Loop(2) = {4, 3, -2, -1};\n"
      "Curve Loop(3) = {-4:-1};\n"
      "Plane Surface(1) = {1};\n");
  ASSERT_EQ(g.loops.size(), 3u);
  EXPECT_EQ(g.loops[0].id, 1);
  EXPECT_EQ(g.loops[0].curves, (std::vector<int>{1, 2, -3, -4}));
  EXPECT_EQ(g.loops[1].curves, (std::vector<int>{4, 3, -2, -1}));
  EXPECT_EQ(g.loops[2].curves, (std::vector<int>{-4, -3, -2, -1}));
  EXPECT_EQ(g.loops[2].line, 5u);
}

TEST(Geo, PhysicalGroupsWithAndWithoutNames) {
  const Geometry2d g = parse_geo(std::string(kSquare) +
                                 "Physical Curve(10) = {1, 2};\n"         // line 5
                                 "Physical Line(\"wall\", 20) = {3};\n"   // line 6
                                 "Physical Curve(\"inlet\") = {4};\n"     // 21
                                 "Physical Surface(\"domain\") = {1};\n"  // 22: any dimension
                                 "Physical Surface(5) = {1};\n"
                                 "Physical Curve(\"a//b\") = {};\n"  // 23, no entities
                                 "Physical Surface(10) = {1};\n");   // 10 again: other dimension
  ASSERT_EQ(g.physical_curves.size(), 4u);
  EXPECT_EQ(g.physical_curves[0].tag, 10);
  EXPECT_EQ(g.physical_curves[0].name, "");
  EXPECT_EQ(g.physical_curves[0].ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(g.physical_curves[0].line, 5u);
  EXPECT_EQ(g.physical_curves[1].tag, 20);
  EXPECT_EQ(g.physical_curves[1].name, "wall");
  EXPECT_EQ(g.physical_curves[1].line, 6u);
  EXPECT_EQ(g.physical_curves[2].tag, 21);
  EXPECT_EQ(g.physical_curves[2].name, "inlet");
  EXPECT_EQ(g.physical_curves[2].ids, (std::vector<int>{4}));
  EXPECT_EQ(g.physical_curves[3].tag, 23);
  EXPECT_EQ(g.physical_curves[3].name, "a//b");
  EXPECT_TRUE(g.physical_curves[3].ids.empty());
  ASSERT_EQ(g.physical_surfaces.size(), 3u);
  EXPECT_EQ(g.physical_surfaces[0].tag, 22);
  EXPECT_EQ(g.physical_surfaces[0].name, "domain");
  EXPECT_EQ(g.physical_surfaces[0].ids, (std::vector<int>{1}));
  EXPECT_EQ(g.physical_surfaces[1].tag, 5);
  EXPECT_EQ(g.physical_surfaces[2].tag, 10);
}

TEST(Geo, FirstAutomaticTagIsOne) {
  const Geometry2d g = parse_geo(std::string(kSquare) + "Physical Surface(\"s\") = {1};\n");
  EXPECT_EQ(g.physical_surfaces.at(0).tag, 1);
}

TEST(Geo, Ranges) {
  const std::string s = kSquare;
  EXPECT_EQ(ids_of("1:4", s), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(ids_of("4:1", s), (std::vector<int>{4, 3, 2, 1}));  // counts down, as in Gmsh
  EXPECT_EQ(ids_of("1:4:2", s), (std::vector<int>{1, 3}));
  EXPECT_EQ(ids_of("4:1:-2", s), (std::vector<int>{4, 2}));
  EXPECT_EQ(ids_of("4:1:1", s), (std::vector<int>{}));  // the step goes away from 4
  EXPECT_EQ(ids_of("3:3", s), (std::vector<int>{3}));
  EXPECT_EQ(ids_of("1:2, 4, 2:3", s), (std::vector<int>{1, 2, 4, 2, 3}));
  EXPECT_EQ(ids_of("n:n+2", s + "n = 2;"), (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(ids_of("1.0:2*2:3/3", s), (std::vector<int>{1, 2, 3, 4}));
}

TEST(Geo, Expressions) {
  EXPECT_EQ(eval("1 + 2 * 3"), 7);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9);
  EXPECT_EQ(eval("10 - 4 - 3"), 3);
  EXPECT_EQ(eval("12 / 3 / 2"), 2);
  EXPECT_EQ(eval("2 * 3^2"), 18);
  EXPECT_EQ(eval("2^3^2"), 512);  // right associative
  EXPECT_EQ(eval("(2^3)^2"), 64);
  EXPECT_EQ(eval("-2^2"), -4);  // ^ before the sign, as in Gmsh
  EXPECT_EQ(eval("2^-1"), 0.5);
  EXPECT_EQ(eval("-(1 - 3)"), 2);
  EXPECT_EQ(eval("+3"), 3);
  EXPECT_EQ(eval("- -3"), 3);
  EXPECT_EQ(eval("1 - -1"), 2);
  EXPECT_EQ(eval("Pi"), std::numbers::pi);
  EXPECT_EQ(eval("2 * Pi / 4"), std::numbers::pi / 2);
  EXPECT_EQ(eval("Sqrt(16)"), 4);
  EXPECT_NEAR(eval("Sin(Pi / 2)"), 1, 1e-15);
  EXPECT_EQ(eval("Cos(0)"), 1);
  EXPECT_NEAR(eval("Tan(Pi / 4)"), 1, 1e-15);
  EXPECT_NEAR(eval("Asin(1)"), std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(eval("Acos(1)"), 0);
  EXPECT_NEAR(eval("Atan(1)"), std::numbers::pi / 4, 1e-15);
  EXPECT_NEAR(eval("Atan2(1, -1)"), 3 * std::numbers::pi / 4, 1e-15);
  EXPECT_NEAR(eval("Exp(1)"), std::numbers::e, 1e-15);
  EXPECT_NEAR(eval("Log(Exp(2))"), 2, 1e-15);
  EXPECT_EQ(eval("Fabs(-3)"), 3);
  EXPECT_EQ(eval("Hypot(3, 4)"), 5);
  EXPECT_EQ(eval("Min(2, 3) + 10 * Max(2, 3)"), 32);
  EXPECT_EQ(eval("Floor(-1.5)"), -2);
  EXPECT_EQ(eval("Ceil(1.2)"), 2);
  EXPECT_EQ(eval("Sqrt(Hypot(3, 4) * 5) ^ 2"), 25);
  // Number forms.
  EXPECT_EQ(eval("1"), 1);
  EXPECT_EQ(eval("1.5"), 1.5);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("1e-3"), 1e-3);
  EXPECT_EQ(eval("2."), 2);
  EXPECT_EQ(eval("1.e2"), 100);
  EXPECT_EQ(eval("1E+2"), 100);
  EXPECT_EQ(eval("0.5e1"), 5);
  // Variables: defined in order, reassigned.
  EXPECT_EQ(eval("b", "a = 2; b = a * 3 + 1; a = 10;"), 7);
  EXPECT_EQ(eval("a", "a = 2; b = a * 3 + 1; a = 10;"), 10);
  EXPECT_EQ(eval("lc_2 + x1", "lc_2 = 1; x1 = 2;"), 3);
}

TEST(Geo, IdsAreExpressions) {
  const Geometry2d g = parse_geo(
      "n = 3;\n"
      "Point(n) = {0, 0, 0}; Point(n + 1) = {1, 0, 0}; Point(10 / 2 * 2) = {2, 0, 0};\n"
      "Point(2.0) = {3, 0, 0};\n"
      "Line(n) = {n, n + 1};\n");
  ASSERT_EQ(g.points.size(), 4u);
  EXPECT_EQ(g.points[0].id, 3);
  EXPECT_EQ(g.points[1].id, 4);
  EXPECT_EQ(g.points[2].id, 10);
  EXPECT_EQ(g.points[3].id, 2);
  EXPECT_EQ(g.curves.at(0).id, 3);
  EXPECT_EQ(g.curves.at(0).points, (std::vector<int>{3, 4}));
}

TEST(Geo, CommentsAndLines) {
  const Geometry2d g = parse_geo(
      "// a comment; Point(9) = {0, 0, 0};\n"
      "/* a block\n"
      "   comment Point(8) = {0, 0, 0}; */ Point(1) = {0, 0, 0}; // trailing\n"
      "Point(2) = {1 /* inline */, 0, 0}; /**/ /***/\n"
      "Point(3)//\n"
      "= {2, 0, 0};\n"
      "// last line without newline");
  ASSERT_EQ(g.points.size(), 3u);
  EXPECT_EQ(g.points[0].id, 1);
  EXPECT_EQ(g.points[0].line, 3u);
  EXPECT_EQ(g.points[1].x, 1.0);
  EXPECT_EQ(g.points[1].line, 4u);
  EXPECT_EQ(g.points[2].line, 5u);
  EXPECT_EQ(error_of("/* 1\n2\n3 */ x = y;"), "line 3: variable 'y' is not defined");
  EXPECT_EQ(error_of("Point(1) = {0, 0, 0}; /*/ Point(2) = {0, 0, 0};\n*/ Line(1) = {1, 2};"),
            "line 2: Line 1 uses point 2, which is not defined");
  EXPECT_EQ(error_of("// x\nPhysical/*\n*/Point(1) = {1};").substr(0, 32),
            "line 2: 'Physical Point' is not ");
}

TEST(Geo, EmptyInputsAndStatements) {
  const Geometry2d g = parse_geo("");
  EXPECT_TRUE(g.points.empty());
  EXPECT_TRUE(parse_geo("\n// nothing\n;;\n").points.empty());
  EXPECT_EQ(parse_geo("\xEF\xBB\xBFPoint(1) = {0, 0, 0};").points.size(), 1u);  // byte order mark
  EXPECT_EQ(parse_geo("Point(1)={0,0,0};Point(2)={1,0,0};Line(1)={1,2};").curves.size(), 1u);
}

TEST(Geo, OptionsAreIgnoredAndListed) {
  const Geometry2d g = parse_geo(
      "Mesh.Algorithm = 6;\n"
      "Point(1) = {0, 0, 0};\n"
      "Geometry.Tolerance = 1e-8; General.Terminal = 1;\n"
      "Mesh.Color.Points = {0, 0, 255};\n"
      "General.Title = \"a;b\";\n"
      "Mesh.CharacteristicLengthMax = undefined_variable * 2;\n");
  EXPECT_EQ(g.points.size(), 1u);
  EXPECT_EQ(g.ignored, (std::vector<std::string>{
                           "line 1: Mesh.Algorithm", "line 3: Geometry.Tolerance",
                           "line 3: General.Terminal", "line 4: Mesh.Color.Points",
                           "line 5: General.Title", "line 6: Mesh.CharacteristicLengthMax"}));
}

TEST(Geo, GmshFileWithHole) {
  const char text[] =
      "lc = 0.05;\n"
      "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; "
      "Point(4) = {0, 1, 0, lc};\n"
      "Point(5) = {0.5, 0.5, 0, lc}; Point(6) = {0.7, 0.5, 0, lc/2}; "
      "Point(7) = {0.3, 0.5, 0, lc/2};\n"
      "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
      "Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 6};\n"
      "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6};\n"
      "Plane Surface(1) = {1, 2};\n"
      "Physical Curve(\"outer\", 1) = {1:4}; Physical Curve(2) = {5, 6};\n"
      "Physical Surface(3) = {1};\n"
      "Mesh.Algorithm = 6;\n";
  EXPECT_EQ(test::read_text(kSquareHole), text);
  for (const Geometry2d& g : {parse_geo(text), read_geo(kSquareHole)}) {
    ASSERT_EQ(g.points.size(), 7u);
    EXPECT_DOUBLE_EQ(g.points[5].x, 0.7);
    EXPECT_DOUBLE_EQ(g.points[5].lc, 0.025);
    EXPECT_EQ(g.points[6].line, 3u);
    ASSERT_EQ(g.curves.size(), 6u);
    EXPECT_EQ(g.curves[4].kind, GeoCurveKind::kCircle);
    EXPECT_EQ(g.curves[4].points, (std::vector<int>{6, 5, 7}));
    EXPECT_EQ(g.curves[5].points, (std::vector<int>{7, 5, 6}));
    ASSERT_EQ(g.loops.size(), 2u);
    EXPECT_EQ(g.loops[1].curves, (std::vector<int>{5, 6}));
    ASSERT_EQ(g.surfaces.size(), 1u);
    EXPECT_EQ(g.surfaces[0].loops, (std::vector<int>{1, 2}));
    ASSERT_EQ(g.physical_curves.size(), 2u);
    EXPECT_EQ(g.physical_curves[0].tag, 1);
    EXPECT_EQ(g.physical_curves[0].name, "outer");
    EXPECT_EQ(g.physical_curves[0].ids, (std::vector<int>{1, 2, 3, 4}));
    EXPECT_EQ(g.physical_curves[1].tag, 2);
    EXPECT_EQ(g.physical_curves[1].ids, (std::vector<int>{5, 6}));
    ASSERT_EQ(g.physical_surfaces.size(), 1u);
    EXPECT_EQ(g.physical_surfaces[0].tag, 3);
    EXPECT_EQ(g.physical_surfaces[0].line, 9u);
    EXPECT_EQ(g.ignored, (std::vector<std::string>{"line 10: Mesh.Algorithm"}));
  }
}

struct BadGeo {
  std::string text;
  std::string message;
};

const char kPoints[] =  // lines 1-2: points 1 (0, 0), 2 (1, 0), 3 (0, 2), 4 (-1, 0)
    "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\n"
    "Point(3) = {0, 2, 0}; Point(4) = {-1, 0, 0};\n";

const char kSupportedList[] =
    " is not supported (read: Point, Line, Circle, Spline, Curve Loop, Plane Surface, Physical "
    "Curve/Surface, variables, Mesh./Geometry./General. options ignored)";

TEST(Geo, Errors) {
  const std::string p = kPoints;   // lines 1-2
  const std::string sq = kSquare;  // lines 1-4
  const BadGeo cases[] = {
      // Variables and expressions.
      {"lc = 0.1;\nPoint(1) = {0, 0, 0, h};\n", "line 2: variable 'h' is not defined"},
      {"x = y;\n/* not closed", "line 1: variable 'y' is not defined"},  // the first error
      {"x = 1;\n\nx = x + 1/0;\n", "line 3: the expression is not finite"},
      {"x = 0/0;", "line 1: the expression is not finite"},
      {"x = Log(0);", "line 1: the expression is not finite"},
      {"x = 1;\ny = Sqrt(-x);", "line 2: the expression is not finite"},
      {"x = 10^400;", "line 1: the expression is not finite"},
      {"x = 1e308 * 10;", "line 1: the expression is not finite"},
      {"x = 1e999;", "line 1: the number 1e999 is out of range"},
      {"x = 1e;", "line 1: malformed number '1e'"},
      {"x = 1.2.3;", "line 1: malformed number '1.2.3'"},
      {"x = 2lc;", "line 1: malformed number '2lc'"},
      {"x = ;", "line 1: expected a number, a variable, a function or '(', found ';'"},
      {"x = 1 +\n;", "line 1: expected a number, a variable, a function or '(', found ';'"},
      {"x = Atan2(1);", "line 1: Atan2 takes 2 arguments, not 1"},
      {"x = Sqrt(1, 2);", "line 1: Sqrt takes 1 argument, not 2"},
      {"x = Sqrt 2;", "line 1: expected '(' after Sqrt, found '2'"},
      {"x = Foo(1);",
       "line 1: 'Foo' is not a function (functions: Sqrt Sin Cos Tan Asin Acos Atan Atan2 Exp Log "
       "Fabs Hypot Min Max Floor Ceil)"},
      {"x = (1 + 2;", "line 1: expected ')' to close the '(' of line 1, found ';'"},
      {"x = " + std::string(2000, '(') + "1" + std::string(2000, ')') + ";",
       "line 1: the expression is nested too deeply"},
      {"Pi = 3;", "line 1: 'Pi' is a reserved name, not a variable"},
      {"Sqrt = 3;", "line 1: 'Sqrt' is a reserved name, not a variable"},
      {"x[] = {1, 2};", "line 1: unexpected character '['"},
      {"x = 1 % 2;", "line 1: unexpected character '%'"},
      {"x = 1;\n\x01", "line 2: unexpected character byte 0x01"},
      {"3 = x;", "line 1: expected a statement, found '3'"},
      {"\"a\";", "line 1: expected a statement, found \"a\""},
      // Syntax: semicolons, brackets, comments, strings.
      {"lc = 0.1\nPoint(1) = {0, 0, 0};",
       "line 1: expected ';' at the end of the assignment to lc, found 'Point'"},
      {"Point(1) = {0, 0, 0}\nPoint(2) = {1, 0, 0};",
       "line 1: expected ';' at the end of the Point 1 statement, found 'Point'"},
      {"Point(1) = {0, 0, 0}",
       "line 1: expected ';' at the end of the Point 1 statement, found "
       "the end of the file"},
      {p + "Line(1) = {1, 2;", "line 3: expected '}' or ',' in the list of Line 1, found ';'"},
      {p + "Line(1) = {1, 2}};",
       "line 3: expected ';' at the end of the Line 1 statement, found '}'"},
      {p + "Line(1) = 1, 2};", "line 3: expected '{' to open the list of Line 1, found '1'"},
      {p + "Line(1 = {1, 2};", "line 3: expected ')' after the Line id, found '='"},
      {p + "Line(1) {1, 2};", "line 3: expected '=' after Line(1), found '{'"},
      {p + "Line 1 = {1, 2};", "line 3: expected '(' after Line, found '1'"},
      {p + "Line(1) = {1, 2\n\n",
       "line 3: expected '}' or ',' in the list of Line 1, found the "
       "end of the file"},
      {p + "Line(1) = {1, 2, };",
       "line 3: expected a number, a variable, a function or '(', found '}'"},
      {"Point(1) = {0, 0, 0};\n/* a\nb\n", "line 2: unterminated /* comment"},
      {"/*/ Point(1) = {0, 0, 0};", "line 1: unterminated /* comment"},
      {sq + "Physical Curve(\"abc) = {1};", "line 5: unterminated string"},
      {sq + "Physical Curve(\"a\nb\") = {1};", "line 5: unterminated string"},
      {"Mesh.Algorithm = 6",
       "line 1: expected ';' at the end of the option Mesh.Algorithm, found "
       "the end of the file"},
      // Unsupported statements.
      {p + "Point{3} In Surface{1};",
       "line 3: 'Point{...} In Surface' (embedded entities)" + std::string(kSupportedList)},
      {"Point(1) = {0, 0, 0};\nExtrude {0, 0, 1} { Point{1}; }",
       "line 2: 'Extrude'" + std::string(kSupportedList)},
      {sq + "\nTransfinite Line{1} = 10;",
       "line 6: 'Transfinite Line'" + std::string(kSupportedList)},
      {sq + "Physical Point(1) = {1};", "line 5: 'Physical Point'" + std::string(kSupportedList)},
      {"SetFactory(\"OpenCASCADE\");", "line 1: 'SetFactory'" + std::string(kSupportedList)},
      {p + "Ellipse(1) = {2, 1, 3, 4};", "line 3: 'Ellipse'" + std::string(kSupportedList)},
      {"For i In {1:3}\nEndFor", "line 1: 'For'" + std::string(kSupportedList)},
      {"View.Light = 0;", "line 1: 'View.Light'" + std::string(kSupportedList)},
      {p + "Curve(1) = {1, 2};", "line 3: 'Curve'" + std::string(kSupportedList)},
      {"point(1) = {0, 0, 0};", "line 1: 'point'" + std::string(kSupportedList)},
      // Points.
      {"Point(1) = {0, 0, 0.5};",
       "line 1: Point 1: z = 0.5, but the geometry must lie in the plane z = 0"},
      {"Point(1) = {0, 0,\n -1e-9, 0.1};",
       "line 2: Point 1: z = -1e-09, but the geometry must lie in the plane z = 0"},
      {"Point(1) = {0, 0, 0, -0.1};", "line 1: Point 1: lc = -0.1 is negative"},
      {"Point(1) = {0, 0};", "line 1: Point 1 has 2 values, expected {x, y, z} or {x, y, z, lc}"},
      {"Point(1) = {0, 0, 0, 1, 2};",
       "line 1: Point 1 has 5 values, expected {x, y, z} or {x, y, z, lc}"},
      {"Point(1) = {0, 0, 0};\n\nPoint(1) = {1, 0, 0};",
       "line 3: point 1 is defined twice (lines 1 and 3)"},
      // Ids.
      {"Point(1.5) = {0, 0, 0};", "line 1: Point id 1.5 is not an integer"},
      {"Point(0) = {0, 0, 0};", "line 1: Point id 0 is not positive"},
      {"Point(-2) = {0, 0, 0};", "line 1: Point id -2 is not positive"},
      {"Point(1e10) = {0, 0, 0};", "line 1: Point id 10000000000 is too large"},
      {p + "Line(1) = {1,\n2.5};", "line 4: Line 1: point id 2.5 is not an integer"},
      {p + "Line(1) = {1, -2};", "line 3: Line 1: point id -2 is not positive"},
      {p + "Line(4) = {1, 9};", "line 3: Line 4 uses point 9, which is not defined"},
      {p + "Line(4) = {1,\n\n 9};", "line 5: Line 4 uses point 9, which is not defined"},
      {sq + "Curve Loop(2) = {1, 0};",
       "line 5: Curve Loop 2: curve id 0 is not valid (-c is curve c reversed)"},
      {sq + "Line Loop(2) = {1, -7};", "line 5: Line Loop 2 uses curve 7, which is not defined"},
      {sq + "Plane Surface(2) = {-1};",
       "line 5: Plane Surface 2: curve loop id -1 is not positive"},
      {sq + "Plane Surface(2) = {2};",
       "line 5: Plane Surface 2 uses curve loop 2, which is not defined"},
      {sq + "Physical Curve(1) = {1, 5};",
       "line 5: Physical Curve 1 uses curve 5, which is not defined"},
      {sq + "Physical Curve(\"x\") = {-1};",
       "line 5: Physical Curve \"x\": curve id -1 is not "
       "positive"},
      {sq + "Physical Surface(1) = {2};",
       "line 5: Physical Surface 1 uses plane surface 2, which is not defined"},
      {sq + "Physical Surface(1.5) = {1};", "line 5: Physical Surface tag 1.5 is not an integer"},
      {sq + "Physical Surface(\"s\", 0) = {1};", "line 5: Physical Surface tag 0 is not positive"},
      {sq + "Line Loop(1) = {1, 2, 3, 4};",
       "line 5: curve loop 1 is defined twice (lines 3 and 5)"},
      {sq + "Plane Surface(1) = {1};", "line 5: plane surface 1 is defined twice (lines 4 and 5)"},
      {sq + "Physical Curve(1) = {1};\nPhysical Line(1) = {2};",
       "line 6: physical curve 1 is defined twice (lines 5 and 6)"},
      {sq + "Physical Curve(\"a\") = {1};\nPhysical Curve(\"a\") = {2};",
       "line 6: Physical Curve \"a\" is defined twice (lines 5 and 6)"},
      {sq + "Physical Surface(7) = {1};\nPhysical Curve(\"x\", 3) = {1};\n"
            "Physical Curve(\"y\") = {2};\nPhysical Curve(8) = {3};",
       "line 8: physical curve 8 is defined twice (lines 7 and 8)"},  // "y" took 8
      // Ranges.
      {sq + "Physical Curve(1) = {1:2.5};", "line 5: the range 1:2.5: bound 2.5 is not an integer"},
      {sq + "Physical Curve(1) = {1:4:0};", "line 5: the range 1:4:0 has a step of 0"},
      {sq + "Physical Curve(1) = {1:4:0.5};",
       "line 5: the range 1:4:0.5: step 0.5 is not an integer"},
      {sq + "Physical Curve(1) = {1:6};",
       "line 5: Physical Curve 1 uses curve 5, which is not defined"},
      {sq + "Physical Curve(1) = {1:100000};",
       "line 5: the range 1:100000 is too long: 100000 values, and 4 curves are defined"},
      {"Point(1) = {0:100000};",
       "line 1: the range 0:100000 is too long: 100001 values, and a Point takes 3 or 4 values"},
      // Curves.
      {p + "Line(1) = {1, 1};", "line 3: Line 1 starts and ends at point 1"},
      {p + "Point(5) = {1, 0, 0};\nLine(1) = {2, 5};",
       "line 4: Line 1 has zero length: points 2 and 5 are at the same place"},
      {p + "Line(1) = {1, 2, 3};", "line 3: Line 1 has 3 points, expected 2 {start, end}"},
      {p + "Line(1) = {1, 2};\nCircle(1) = {2, 1, 4};",
       "line 4: curve 1 is defined twice (lines 3 and 4)"},
      {p + "Circle(1) = {2, 1, 3};",
       "line 3: Circle 1: its start (point 2) and end (point 3) are at different distances from "
       "the centre (point 1): 1 and 2"},
      {p + "Point(5) = {0, 1.00001, 0};\nCircle(1) = {2, 1, 5};",
       "line 4: Circle 1: its start (point 2) and end (point 5) are at different distances from "
       "the centre (point 1): 1 and 1.00001"},
      {p + "Circle(1) = {1, 1, 2};",
       "line 3: Circle 1 has radius 0: point 1 is at the centre "
       "(point 1)"},
      {p + "Circle(1) = {2, 1, 2};",
       "line 3: Circle 1 starts and ends at the same place (points 2 and 2)"},
      {p + "Circle(1) = {2, 1};", "line 3: Circle 1 has 2 points, expected 3 {start, centre, end}"},
      {p + "Spline(1) = {1};", "line 3: Spline 1 has 1 point, expected at least 2"},
      {p + "Spline(1) = {};", "line 3: Spline 1 has 0 points, expected at least 2"},
      {p + "Spline(1) = {1, 2, 2, 3};", "line 3: Spline 1 goes through point 2 twice in a row"},
      {p + "Spline(1) = {1, 2, 1};",
       "line 3: Spline 1 is closed (first point = last) but goes through fewer than 3 points"},
      {sq + "Curve Loop(2) = {};", "line 5: Curve Loop 2 has no curves"},
      {sq + "Plane Surface(2) = {};", "line 5: Plane Surface 2 has no curve loops"},
  };
  for (const BadGeo& c : cases) EXPECT_EQ(error_of(c.text), c.message) << c.text;
}

TEST(Geo, ReadGeoErrorsNameTheFile) {
  test::ScratchDir dir;
  const std::string path = dir.file("bad.geo");
  test::write_text(path, std::string(kPoints) + "\nLine(4) = {1, 9};\n");
  try {
    read_geo(path);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":4: Line 4 uses point 9, which is not defined");
  }
  const std::string missing = dir.file("missing.geo");
  try {
    read_geo(missing);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(missing + ": cannot open", 0), 0u) << e.what();
  }
}

TEST(Geo, GmshAcceptsTheTestFile) {
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh is not installed";
  test::ScratchDir dir;
  const std::string out = dir.file("square_hole.msh");
  const std::string command =
      "gmsh '" + kSquareHole + "' -2 -format msh22 -o '" + out + "' >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string msh = test::read_text(out);
  EXPECT_NE(msh.find("1 1 \"outer\""), std::string::npos);
}

TEST(Geo, AutomaticTagsMatchGmsh) {
  // Gmsh numbers a physical group given by name only after the largest physical tag so far,
  // of any dimension.
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh is not installed";
  const std::string text = std::string(kSquare) +
                           "Physical Curve(3) = {1};\n"
                           "Physical Surface(\"s\") = {1};\n"
                           "Physical Curve(\"c\") = {2};\n";
  const Geometry2d g = parse_geo(text);
  ASSERT_EQ(g.physical_surfaces.size(), 1u);
  EXPECT_EQ(g.physical_surfaces[0].tag, 4);
  EXPECT_EQ(g.physical_curves.at(1).tag, 5);
  test::ScratchDir dir;
  const std::string geo = dir.file("tags.geo");
  const std::string out = dir.file("tags.msh");
  test::write_text(geo, text);
  const std::string command =
      "gmsh '" + geo + "' -2 -format msh22 -o '" + out + "' >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string msh = test::read_text(out);
  EXPECT_NE(msh.find("2 4 \"s\""), std::string::npos) << msh.substr(0, 300);
  EXPECT_NE(msh.find("1 5 \"c\""), std::string::npos) << msh.substr(0, 300);
}

}  // namespace
}  // namespace riemesh
