#pragma once
// Tokens and arithmetic of the .geo reader (io/geo.hpp): a lexer that reads the text one token at
// a time (so that the first error in the file is the one reported) and an evaluator of numeric
// expressions over the variables defined so far. Errors are InputError "line N: message".
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace riemesh::geo_detail {

enum class TokenKind { kEnd, kIdentifier, kNumber, kString, kPunct };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  /// Identifier (a dotted name such as Mesh.Algorithm is one identifier), number as written,
  /// string without its quotes, or the punctuation character.
  std::string_view text;
  double number = 0.0;
  std::size_t line = 0;

  bool is(char punct) const { return kind == TokenKind::kPunct && text[0] == punct; }
  bool is(std::string_view word) const { return kind == TokenKind::kIdentifier && text == word; }
};

/// Throws InputError "line N: what".
[[noreturn]] void fail(std::size_t line, const std::string& what);

/// text between two `mark`s: 'x', "name".
std::string quote(std::string_view text, char mark);

/// A token for messages: 'Point', ';', "name", the end of the file.
std::string describe(const Token& token);

/// v for messages: integers in full (100000), others as the shortest text that reads back.
std::string format_number(double v);

/// True for the words of the language (Point, Line, Pi, Sqrt, ...), which cannot be variables.
bool is_reserved(std::string_view word);

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  /// The next token, not consumed (scanned on first use).
  const Token& peek();
  Token next();
  /// Consumes the next token if it is `punct`.
  bool accept(char punct);
  /// Consumes `punct` or fails "expected 'punct' CONTEXT, found X" on the line of the last token.
  void expect(char punct, std::string_view context);
  /// Line of the last token consumed (1 before the first).
  std::size_t line() const { return last_line_; }

 private:
  Token scan();
  void skip_blanks();

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t last_line_ = 1;
  Token peeked_;
  bool has_peeked_ = false;
};

using Variables = std::map<std::string, double, std::less<>>;

/// Reads one expression at the lexer's position and returns its value, finite.
double parse_expression(Lexer& in, const Variables& variables);

}  // namespace riemesh::geo_detail
