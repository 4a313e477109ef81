#include "io/geo.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/geo_expression.hpp"

namespace riemesh {

namespace {

using geo_detail::describe;
using geo_detail::fail;
using geo_detail::format_number;
using geo_detail::Lexer;
using geo_detail::quote;
using geo_detail::Token;
using geo_detail::TokenKind;

const char kSupported[] =
    "(read: Point, Line, Circle, Spline, Curve Loop, Plane Surface, Physical Curve/Surface, "
    "variables, Mesh./Geometry./General. options ignored)";

/// A value of a { list }, with the line it was written on.
struct Item {
  double value;
  std::size_t line;
};

/// Ids of one kind of entity: id -> index in its vector of the Geometry2d.
using IdIndex = std::unordered_map<int, std::size_t>;

bool is_option(std::string_view name) {
  return name.starts_with("Mesh.") || name.starts_with("Geometry.") || name.starts_with("General.");
}

/// v (finite) as an int: an error naming `what` unless it is an integer that fits.
int integer(double v, std::size_t line, const std::string& what) {
  if (v != std::trunc(v)) fail(line, what + " " + format_number(v) + " is not an integer");
  if (std::fabs(v) > INT_MAX) fail(line, what + " " + format_number(v) + " is too large");
  return static_cast<int>(v);
}

std::string plural(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// "1 point is defined", "4 curves are defined".
std::string defined(std::size_t n, const char* noun) {
  return plural(n, noun) + (n == 1 ? " is defined" : " are defined");
}

/// Statement by statement: syntax, then the checks of the statement once its ';' is read (the
/// lexer does not read past it, so an error further on is never reported first).
class Parser {
 public:
  explicit Parser(std::string_view text) : in_(text) {}

  Geometry2d run() {
    while (in_.peek().kind != TokenKind::kEnd) statement();
    return std::move(geo_);
  }

 private:
  void statement();
  void assignment(const Token& name);
  void option(const Token& name);
  [[noreturn]] void unsupported(const Token& head);
  /// "(id) =": a positive integer id; `keyword` as written (Point, Line Loop, ...).
  int entity_id(const std::string& keyword);
  /// "{ a, b:c, d:e:s }". A range may not expand to more than max(limit, 1000) values: it would
  /// name an id that is not defined (`known` says what there is, for the message).
  std::vector<Item> list(const std::string& owner, std::size_t limit, const std::string& known);
  void end_statement(const std::string& owner) {
    in_.expect(';', "at the end of the " + owner + " statement");
  }
  /// An id of a list: an integer, nonzero, positive unless `reversible`, defined in `index`.
  int reference(const Item& item, const std::string& owner, const char* kind, const IdIndex& index,
                bool reversible) const;
  template <class Entity>
  void check_new(const IdIndex& index, const std::vector<Entity>& entities, int id,
                 std::size_t line, const char* kind) const;

  void point(const Token& head);
  void curve(const Token& head, GeoCurveKind kind);
  void loop(const Token& head, const std::string& keyword);
  void surface(const Token& head);
  void physical(const Token& head, const Token& sub);

  const GeoPoint& point_at(int id) const { return geo_.points[points_.at(id)]; }

  Lexer in_;
  geo_detail::Variables variables_;
  Geometry2d geo_;
  IdIndex points_, curves_, loops_, surfaces_, physical_curves_, physical_surfaces_;
  int max_physical_tag_ = 0;  // over both dimensions, as in Gmsh
};

void Parser::statement() {
  const Token head = in_.next();
  if (head.is(';')) return;  // empty statement
  if (head.kind != TokenKind::kIdentifier)
    fail(head.line, "expected a statement, found " + describe(head));
  const std::string_view word = head.text;
  if (is_option(word)) return option(head);
  const bool dotted = word.find('.') != std::string_view::npos;
  if (!dotted && in_.peek().is('=') && !geo_detail::is_reserved(word)) return assignment(head);
  // 'Point{5} In Surface{1};', 'Curve{2} In Surface{1};' (embedded entities): not read.
  if ((word == "Point" || word == "Line" || word == "Curve") && in_.peek().is('{'))
    fail(head.line, "'" + std::string(word) +
                        "{...} In Surface' (embedded entities) is not supported " + kSupported);
  if (word == "Point") return point(head);
  if (word == "Circle") return curve(head, GeoCurveKind::kCircle);
  if (word == "Spline") return curve(head, GeoCurveKind::kSpline);
  if (word == "Line") {
    if (!in_.peek().is("Loop")) return curve(head, GeoCurveKind::kLine);
    in_.next();
    return loop(head, "Line Loop");
  }
  if (word == "Curve" && in_.peek().is("Loop")) {
    in_.next();
    return loop(head, "Curve Loop");
  }
  if (word == "Plane" && in_.peek().is("Surface")) {
    in_.next();
    return surface(head);
  }
  if (word == "Physical") {
    const Token& sub = in_.peek();
    if (sub.is("Curve") || sub.is("Line") || sub.is("Surface")) return physical(head, in_.next());
  }
  if (in_.peek().is('=') && geo_detail::is_reserved(word))
    fail(head.line, quote(word, '\'') + " is a reserved name, not a variable");
  unsupported(head);
}

void Parser::unsupported(const Token& head) {
  // Name the command by its words: 'Extrude', 'Transfinite Line', 'Physical Point'.
  std::string name(head.text);
  const Token& after = in_.peek();
  if (after.kind == TokenKind::kIdentifier && after.text[0] >= 'A' && after.text[0] <= 'Z' &&
      name.find('.') == std::string::npos) {
    name += ' ';
    name += after.text;
  }
  fail(head.line, "'" + name + "' is not supported " + kSupported);
}

void Parser::assignment(const Token& name) {
  const std::string variable(name.text);
  in_.next();  // '='
  const double value = geo_detail::parse_expression(in_, variables_);
  in_.expect(';', "at the end of the assignment to " + variable);
  variables_[variable] = value;
}

void Parser::option(const Token& name) {
  // The value is not read: options may take strings, lists or other options.
  while (!in_.accept(';')) {
    if (in_.peek().kind == TokenKind::kEnd)
      fail(in_.line(), "expected ';' at the end of the option " + std::string(name.text) +
                           ", found the end of the file");
    in_.next();
  }
  geo_.ignored.push_back("line " + std::to_string(name.line) + ": " + std::string(name.text));
}

int Parser::entity_id(const std::string& keyword) {
  in_.expect('(', "after " + keyword);
  const std::size_t line = in_.peek().line;
  const double v = geo_detail::parse_expression(in_, variables_);
  const int id = integer(v, line, keyword + " id");
  if (id <= 0) fail(line, keyword + " id " + std::to_string(id) + " is not positive");
  in_.expect(')', "after the " + keyword + " id");
  in_.expect('=', "after " + keyword + "(" + std::to_string(id) + ")");
  return id;
}

std::vector<Item> Parser::list(const std::string& owner, std::size_t limit,
                               const std::string& known) {
  in_.expect('{', "to open the list of " + owner);
  std::vector<Item> items;
  if (in_.accept('}')) return items;
  limit = std::max<std::size_t>(limit, 1000);
  do {
    const std::size_t line = in_.peek().line;
    const double a = geo_detail::parse_expression(in_, variables_);
    if (!in_.accept(':')) {
      items.push_back({a, line});
      continue;
    }
    // a:b counts down when b < a; a:b:s stops before passing b (empty if s goes the wrong way).
    const double b = geo_detail::parse_expression(in_, variables_);
    const bool stepped = in_.accept(':');
    const double s = stepped ? geo_detail::parse_expression(in_, variables_) : (b < a ? -1 : 1);
    std::string text = format_number(a);
    text += ':';
    text += format_number(b);
    if (stepped) {
      text += ':';
      text += format_number(s);
    }
    const std::int64_t first = integer(a, line, "the range " + text + ": bound");
    const std::int64_t last = integer(b, line, "the range " + text + ": bound");
    const std::int64_t step = integer(s, line, "the range " + text + ": step");
    if (step == 0) fail(line, "the range " + text + " has a step of 0");
    const std::int64_t span = step > 0 ? last - first : first - last;
    const std::int64_t count = span < 0 ? 0 : span / (step > 0 ? step : -step) + 1;
    if (static_cast<std::uint64_t>(count) > limit)
      fail(line, "the range " + text + " is too long: " + std::to_string(count) + " values, and " +
                     known);
    for (std::int64_t k = 0; k < count; ++k)
      items.push_back({static_cast<double>(first + k * step), line});
  } while (in_.accept(','));
  in_.expect('}', "or ',' in the list of " + owner);
  return items;
}

int Parser::reference(const Item& item, const std::string& owner, const char* kind,
                      const IdIndex& index, bool reversible) const {
  const int id = integer(item.value, item.line, owner + ": " + kind + " id");
  if (id == 0 || (id < 0 && !reversible))
    fail(item.line,
         owner + ": " + kind + " id " + std::to_string(id) +
             (reversible ? " is not valid (-c is curve c reversed)" : " is not positive"));
  const int n = id < 0 ? -id : id;
  if (!index.contains(n))
    fail(item.line, owner + " uses " + kind + " " + std::to_string(n) + ", which is not defined");
  return id;
}

template <class Entity>
void Parser::check_new(const IdIndex& index, const std::vector<Entity>& entities, int id,
                       std::size_t line, const char* kind) const {
  const auto it = index.find(id);
  if (it != index.end())
    fail(line, std::string(kind) + " " + std::to_string(id) + " is defined twice (lines " +
                   std::to_string(entities[it->second].line) + " and " + std::to_string(line) +
                   ")");
}

void Parser::point(const Token& head) {
  const int id = entity_id("Point");
  const std::string owner = "Point " + std::to_string(id);
  const std::vector<Item> v = list(owner, 4, "a Point takes 3 or 4 values");
  end_statement(owner);
  if (v.size() != 3 && v.size() != 4)
    fail(head.line,
         owner + " has " + plural(v.size(), "value") + ", expected {x, y, z} or {x, y, z, lc}");
  if (v[2].value != 0.0)
    fail(v[2].line, owner + ": z = " + format_number(v[2].value) +
                        ", but the geometry must lie in the plane z = 0");
  if (v.size() == 4 && v[3].value < 0.0)
    fail(v[3].line, owner + ": lc = " + format_number(v[3].value) + " is negative");
  check_new(points_, geo_.points, id, head.line, "point");
  points_.emplace(id, geo_.points.size());
  geo_.points.push_back({id, v[0].value, v[1].value, v.size() == 4 ? v[3].value : 0.0, head.line});
}

void Parser::curve(const Token& head, GeoCurveKind kind) {
  const std::string keyword(head.text);
  const int id = entity_id(keyword);
  const std::string owner = keyword + " " + std::to_string(id);
  const std::vector<Item> v = list(owner, geo_.points.size(), defined(geo_.points.size(), "point"));
  end_statement(owner);
  const std::size_t needed = kind == GeoCurveKind::kLine     ? 2
                             : kind == GeoCurveKind::kCircle ? 3
                                                             : 0;
  if (needed != 0 && v.size() != needed)
    fail(head.line, owner + " has " + plural(v.size(), "point") + ", expected " +
                        (needed == 2 ? "2 {start, end}" : "3 {start, centre, end}"));
  if (v.size() < 2)
    fail(head.line, owner + " has " + plural(v.size(), "point") + ", expected at least 2");
  GeoCurve c{id, kind, {}, head.line};
  for (const Item& item : v) c.points.push_back(reference(item, owner, "point", points_, false));
  const std::string first = std::to_string(c.points.front());
  const std::string last = std::to_string(c.points.back());
  if (kind == GeoCurveKind::kLine) {
    if (c.points[0] == c.points[1]) fail(head.line, owner + " starts and ends at point " + first);
    const GeoPoint& a = point_at(c.points[0]);
    const GeoPoint& b = point_at(c.points[1]);
    if (a.x == b.x && a.y == b.y)
      fail(head.line,
           owner + " has zero length: points " + first + " and " + last + " are at the same place");
  } else if (kind == GeoCurveKind::kCircle) {
    const GeoPoint& s = point_at(c.points[0]);
    const GeoPoint& o = point_at(c.points[1]);
    const GeoPoint& e = point_at(c.points[2]);
    const std::string centre = "the centre (point " + std::to_string(c.points[1]) + ")";
    const double rs = std::hypot(s.x - o.x, s.y - o.y);
    const double re = std::hypot(e.x - o.x, e.y - o.y);
    if (rs == 0.0 || re == 0.0)
      fail(head.line,
           owner + " has radius 0: point " + (rs == 0.0 ? first : last) + " is at " + centre);
    if (std::fabs(rs - re) > 1e-6 * std::max(rs, re))
      fail(head.line, owner + ": its start (point " + first + ") and end (point " + last +
                          ") are at different distances from " + centre + ": " + format_number(rs) +
                          " and " + format_number(re));
    if (std::hypot(s.x - e.x, s.y - e.y) <= 1e-9 * rs)
      fail(head.line,
           owner + " starts and ends at the same place (points " + first + " and " + last + ")");
    // Start and end opposite across the centre are accepted: Gmsh takes that arc of pi
    // counter-clockwise (normal +z), and files rely on it (two half circles make a hole).
  } else {
    for (std::size_t i = 1; i < c.points.size(); ++i)
      if (c.points[i] == c.points[i - 1])
        fail(v[i].line,
             owner + " goes through point " + std::to_string(c.points[i]) + " twice in a row");
    if (c.points.size() < 4 && c.points.front() == c.points.back())
      fail(head.line, owner +
                          " is closed (first point = last) but goes through fewer than 3 "
                          "points");
  }
  check_new(curves_, geo_.curves, id, head.line, "curve");
  curves_.emplace(id, geo_.curves.size());
  geo_.curves.push_back(std::move(c));
}

void Parser::loop(const Token& head, const std::string& keyword) {
  const int id = entity_id(keyword);
  const std::string owner = keyword + " " + std::to_string(id);
  const std::vector<Item> v = list(owner, geo_.curves.size(), defined(geo_.curves.size(), "curve"));
  end_statement(owner);
  if (v.empty()) fail(head.line, owner + " has no curves");
  GeoLoop l{id, {}, head.line};
  for (const Item& item : v) l.curves.push_back(reference(item, owner, "curve", curves_, true));
  check_new(loops_, geo_.loops, id, head.line, "curve loop");
  loops_.emplace(id, geo_.loops.size());
  geo_.loops.push_back(std::move(l));
}

void Parser::surface(const Token& head) {
  const int id = entity_id("Plane Surface");
  const std::string owner = "Plane Surface " + std::to_string(id);
  const std::vector<Item> v =
      list(owner, geo_.loops.size(), defined(geo_.loops.size(), "curve loop"));
  end_statement(owner);
  if (v.empty()) fail(head.line, owner + " has no curve loops");
  GeoSurface s{id, {}, head.line};
  for (const Item& item : v) s.loops.push_back(reference(item, owner, "curve loop", loops_, false));
  check_new(surfaces_, geo_.surfaces, id, head.line, "plane surface");
  surfaces_.emplace(id, geo_.surfaces.size());
  geo_.surfaces.push_back(std::move(s));
}

void Parser::physical(const Token& head, const Token& sub) {
  const bool surfaces = sub.is("Surface");
  const std::string keyword = "Physical " + std::string(sub.text);
  in_.expect('(', "after " + keyword);
  std::string name;
  bool tagged = true;
  if (in_.peek().kind == TokenKind::kString) {
    name = std::string(in_.next().text);
    tagged = in_.accept(',');
  }
  int tag = 0;
  if (tagged) {
    const std::size_t line = in_.peek().line;
    tag = integer(geo_detail::parse_expression(in_, variables_), line, keyword + " tag");
    if (tag <= 0) fail(line, keyword + " tag " + std::to_string(tag) + " is not positive");
  }
  in_.expect(')', "after the " + keyword + (tagged ? " tag" : " name"));
  std::string owner = keyword;
  if (tagged) owner.append(" ").append(std::to_string(tag));
  if (!name.empty()) owner.append(" ").append(quote(name, '"'));
  in_.expect('=', "after " + keyword + "(...)");
  const std::size_t count = surfaces ? geo_.surfaces.size() : geo_.curves.size();
  const char* kind = surfaces ? "plane surface" : "curve";
  const std::vector<Item> v = list(owner, count, defined(count, kind));
  end_statement(owner);

  std::vector<GeoPhysical>& groups = surfaces ? geo_.physical_surfaces : geo_.physical_curves;
  IdIndex& index = surfaces ? physical_surfaces_ : physical_curves_;
  if (!tagged) {
    // Gmsh: a name alone takes the tag of that name if it exists (here an error: a group is
    // defined once), else 1 + the largest physical tag so far, of any dimension.
    for (const GeoPhysical& g : groups)
      if (g.name == name)
        fail(head.line, keyword + " \"" + name + "\" is defined twice (lines " +
                            std::to_string(g.line) + " and " + std::to_string(head.line) + ")");
    if (max_physical_tag_ == INT_MAX) fail(head.line, owner + ": no tag left");
    tag = max_physical_tag_ + 1;
  }
  const std::string noun = surfaces ? "physical surface" : "physical curve";
  check_new(index, groups, tag, head.line, noun.c_str());
  GeoPhysical g{tag, name, {}, head.line};
  for (const Item& item : v)
    g.ids.push_back(reference(item, owner, kind, surfaces ? surfaces_ : curves_, false));
  max_physical_tag_ = std::max(max_physical_tag_, tag);
  index.emplace(tag, groups.size());
  groups.push_back(std::move(g));
}

}  // namespace

Geometry2d parse_geo(std::string_view text) { return Parser(text).run(); }

std::string geo_message(const std::string& path, std::string_view message) {
  if (message.starts_with("line ")) return path + ":" + std::string(message.substr(5));
  return path + ": " + std::string(message);
}

Geometry2d read_geo(const std::string& path) {
  const std::string text = read_file_bytes(path);  // "PATH: cannot open for reading: ..."
  try {
    return parse_geo(text);
  } catch (const InputError& e) {
    throw InputError(geo_message(path, e.what()));
  }
}

}  // namespace riemesh
