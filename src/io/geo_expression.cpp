#include "io/geo_expression.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <system_error>

#include "core/error.hpp"

namespace riemesh::geo_detail {

namespace {

struct Function {
  std::string_view name;
  int arity;
  double (*one)(double);
  double (*two)(double, double);
};

// Gmsh's names (case matters, as in Gmsh).
const Function kFunctions[] = {
    {"Sqrt", 1, [](double x) { return std::sqrt(x); }, nullptr},
    {"Sin", 1, [](double x) { return std::sin(x); }, nullptr},
    {"Cos", 1, [](double x) { return std::cos(x); }, nullptr},
    {"Tan", 1, [](double x) { return std::tan(x); }, nullptr},
    {"Asin", 1, [](double x) { return std::asin(x); }, nullptr},
    {"Acos", 1, [](double x) { return std::acos(x); }, nullptr},
    {"Atan", 1, [](double x) { return std::atan(x); }, nullptr},
    {"Atan2", 2, nullptr, [](double y, double x) { return std::atan2(y, x); }},
    {"Exp", 1, [](double x) { return std::exp(x); }, nullptr},
    {"Log", 1, [](double x) { return std::log(x); }, nullptr},
    {"Fabs", 1, [](double x) { return std::fabs(x); }, nullptr},
    {"Hypot", 2, nullptr, [](double x, double y) { return std::hypot(x, y); }},
    {"Min", 2, nullptr, [](double x, double y) { return std::fmin(x, y); }},
    {"Max", 2, nullptr, [](double x, double y) { return std::fmax(x, y); }},
    {"Floor", 1, [](double x) { return std::floor(x); }, nullptr},
    {"Ceil", 1, [](double x) { return std::ceil(x); }, nullptr},
};

const char kFunctionList[] =
    "Sqrt Sin Cos Tan Asin Acos Atan Atan2 Exp Log Fabs Hypot Min Max Floor Ceil";

const Function* find_function(std::string_view name) {
  for (const Function& f : kFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

// The statement words of io/geo.cpp and the words of expressions.
const std::string_view kKeywords[] = {"Point", "Line",  "Circle",  "Spline",   "Curve",
                                      "Loop",  "Plane", "Surface", "Physical", "Pi"};

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word_char(char c) { return is_letter(c) || is_digit(c); }

std::string describe_char(char c) {
  if (c > ' ' && c < 127) return std::string("'") + c + "'";
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "byte 0x%02X", static_cast<unsigned>(c) & 0xFFu);
  return buffer;
}

/// Recursive descent over Gmsh's precedences: + - below * / below unary - + below ^ (right
/// associative: 2^3^2 = 2^9, -2^2 = -4, 2^-1 = 0.5). Every intermediate value must be finite.
class Evaluator {
 public:
  Evaluator(Lexer& in, const Variables& variables) : in_(in), variables_(variables) {}

  double sum() {
    double v = product();
    while (in_.peek().is('+') || in_.peek().is('-')) {
      const Token op = in_.next();
      const double r = product();
      v = finite(op.is('+') ? v + r : v - r, op.line);
    }
    return v;
  }

 private:
  static constexpr int kMaxDepth = 500;  // nesting of parentheses and signs (the stack)

  static double finite(double v, std::size_t line) {
    if (!std::isfinite(v)) fail(line, "the expression is not finite");
    return v;
  }

  double product() {
    double v = unary();
    while (in_.peek().is('*') || in_.peek().is('/')) {
      const Token op = in_.next();
      const double r = unary();
      v = finite(op.is('*') ? v * r : v / r, op.line);
    }
    return v;
  }

  double unary() {
    if (++depth_ > kMaxDepth) fail(in_.line(), "the expression is nested too deeply");
    double v = 0.0;
    if (in_.accept('-')) {
      v = -unary();
    } else if (in_.accept('+')) {
      v = unary();
    } else {
      v = power();
    }
    --depth_;
    return v;
  }

  double power() {
    const double base = primary();
    if (!in_.peek().is('^')) return base;
    const Token op = in_.next();
    const double exponent = unary();
    return finite(std::pow(base, exponent), op.line);
  }

  double primary() {
    const Token t = in_.peek();
    if (t.kind == TokenKind::kNumber) {
      in_.next();
      return t.number;
    }
    if (t.is('(')) {
      in_.next();
      const double v = sum();
      in_.expect(')', "to close the '(' of line " + std::to_string(t.line));
      return v;
    }
    if (t.kind != TokenKind::kIdentifier)
      fail(in_.line(), "expected a number, a variable, a function or '(', found " + describe(t));
    in_.next();
    if (t.text == "Pi") return std::numbers::pi;
    if (const Function* f = find_function(t.text)) return call(t, *f);
    if (in_.peek().is('('))
      fail(t.line, quote(t.text, '\'') + " is not a function (functions: " + kFunctionList + ")");
    const auto it = variables_.find(t.text);
    if (it == variables_.end())
      fail(t.line, "variable '" + std::string(t.text) + "' is not defined");
    return it->second;
  }

  double call(const Token& name, const Function& f) {
    const std::string fname(name.text);
    in_.expect('(', "after " + fname);
    double args[2] = {0.0, 0.0};
    int n = 0;
    if (!in_.peek().is(')')) {
      do {
        const double v = sum();
        if (n < 2) args[n] = v;
        ++n;
      } while (in_.accept(','));
    }
    in_.expect(')', "to close the arguments of " + fname);
    if (n != f.arity)
      fail(name.line, fname + " takes " + std::to_string(f.arity) +
                          (f.arity == 1 ? " argument" : " arguments") + ", not " +
                          std::to_string(n));
    return finite(f.arity == 1 ? f.one(args[0]) : f.two(args[0], args[1]), name.line);
  }

  Lexer& in_;
  const Variables& variables_;
  int depth_ = 0;
};

}  // namespace

void fail(std::size_t line, const std::string& what) {
  throw InputError("line " + std::to_string(line) + ": " + what);
}

std::string quote(std::string_view text, char mark) {
  std::string s;
  s.reserve(text.size() + 2);
  s += mark;
  s += text;
  s += mark;
  return s;
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::kEnd:
      return "the end of the file";
    case TokenKind::kString:
      return quote(token.text, '"');
    default:
      return quote(token.text, '\'');
  }
}

std::string format_number(double v) {
  if (v == std::trunc(v) && std::fabs(v) < 1e15)  // integers in full: 100000, not 1e+05
    return std::to_string(static_cast<long long>(v));
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

bool is_reserved(std::string_view word) {
  for (std::string_view k : kKeywords)
    if (k == word) return true;
  return find_function(word) != nullptr;
}

const Token& Lexer::peek() {
  if (!has_peeked_) {
    peeked_ = scan();
    has_peeked_ = true;
  }
  return peeked_;
}

Token Lexer::next() {
  const Token t = peek();
  has_peeked_ = false;
  if (t.kind != TokenKind::kEnd) last_line_ = t.line;  // at the end: the last real token's
  return t;
}

bool Lexer::accept(char punct) {
  if (!peek().is(punct)) return false;
  next();
  return true;
}

void Lexer::expect(char punct, std::string_view context) {
  if (accept(punct)) return;
  fail(last_line_, std::string("expected '") + punct + "' " + std::string(context) + ", found " +
                       describe(peek()));
}

void Lexer::skip_blanks() {
  if (pos_ == 0 && text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // UTF-8 byte order mark
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    const char d = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '/' && d == '/') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else if (c == '/' && d == '*') {
      const std::size_t end = text_.find("*/", pos_ + 2);
      if (end == std::string_view::npos) fail(line_, "unterminated /* comment");
      for (std::size_t i = pos_; i < end; ++i) line_ += text_[i] == '\n';
      pos_ = end + 2;
    } else {
      return;
    }
  }
}

Token Lexer::scan() {
  skip_blanks();
  Token t;
  t.line = line_;
  if (pos_ >= text_.size()) return t;
  const std::size_t begin = pos_;
  const char c = text_[pos_];
  const char d = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
  if (is_letter(c)) {
    // A dotted name (Mesh.Algorithm) is one identifier.
    while (pos_ < text_.size() && is_word_char(text_[pos_])) ++pos_;
    while (pos_ + 1 < text_.size() && text_[pos_] == '.' && is_letter(text_[pos_ + 1])) {
      ++pos_;
      while (pos_ < text_.size() && is_word_char(text_[pos_])) ++pos_;
    }
    t.kind = TokenKind::kIdentifier;
  } else if (is_digit(c) || (c == '.' && is_digit(d))) {
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    const auto r = std::from_chars(first, last, t.number);
    pos_ += static_cast<std::size_t>(r.ptr - first);
    const bool glued = pos_ < text_.size() && (is_word_char(text_[pos_]) || text_[pos_] == '.');
    if (r.ec == std::errc::invalid_argument || r.ptr == first || glued) {
      while (pos_ < text_.size() && (is_word_char(text_[pos_]) || text_[pos_] == '.')) ++pos_;
      fail(line_, "malformed number '" + std::string(text_.substr(begin, pos_ - begin)) + "'");
    }
    if (r.ec == std::errc::result_out_of_range)
      fail(line_,
           "the number " + std::string(text_.substr(begin, pos_ - begin)) + " is out of range");
    t.kind = TokenKind::kNumber;
  } else if (c == '"') {
    const std::size_t close = text_.find_first_of("\"\n", pos_ + 1);
    if (close == std::string_view::npos || text_[close] != '"') fail(line_, "unterminated string");
    t.kind = TokenKind::kString;
    t.text = text_.substr(pos_ + 1, close - pos_ - 1);
    pos_ = close + 1;
    return t;
  } else if (c != '\0' && std::strchr("(){},;=+-*/^:", c)) {
    ++pos_;
    t.kind = TokenKind::kPunct;
  } else {
    fail(line_, "unexpected character " + describe_char(c));
  }
  t.text = text_.substr(begin, pos_ - begin);
  return t;
}

double parse_expression(Lexer& in, const Variables& variables) {
  return Evaluator(in, variables).sum();
}

}  // namespace riemesh::geo_detail
