#include "scene/toml_guard.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "scene/scene.h"

namespace cb::scene_detail {

namespace {

// One code point of UTF-8 at text[i]: its value and length, or length 0 when the bytes are
// not UTF-8 (overlong forms, surrogates and values past U+10FFFF included, as in RFC 3629).
struct CodePoint {
  char32_t value = 0;
  std::size_t length = 0;
};

CodePoint decode(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return {lead, 1};
  std::size_t length = 0;
  char32_t value = 0, least = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2, value = lead & 0x1F, least = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, value = lead & 0x0F, least = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, value = lead & 0x07, least = 0x10000;
  } else {
    return {};
  }
  if (i + length > text.size()) return {};
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return {};
    value = (value << 6) | (byte(i + k) & 0x3F);
  }
  if (value < least || value > 0x10FFFF || (value >= 0xD800 && value <= 0xDFFF)) return {};
  return {value, length};
}

std::string hex(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

bool is_bare_key_start(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '"' || c == '\'';
}

enum class State { Normal, Comment, Basic, Literal, MultiBasic, MultiLiteral };

// Walks the text as toml++ would tokenise it, as far as strings, comments and table headers
// go (that is all the guard needs to know), keeping line and column for messages.
class Scanner {
 public:
  Scanner(std::string_view text, const std::string& where) : text_(text), where_(where) {}

  void run() {
    // A byte order mark opens a file; toml++ skips it.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;
    while (i_ < text_.size()) step();
  }

 private:
  std::string_view text_;
  const std::string& where_;
  std::size_t i_ = 0;
  int line_ = 1, column_ = 1;
  State state_ = State::Normal;
  // Where toml++ stands between tokens: a quote opens a string only where a key or a value
  // begins; elsewhere ("0'x", "2x.y='x'", "2['x'") toml++ reads it as part of a bare value,
  // character by character, and so do '=', '[' and '{' there.
  enum class Expect { Key, Value, Other };
  Expect expect_ = Expect::Key;
  bool in_key_ = false;            // a '.' continues a dotted key
  std::string open_;               // the '[' and '{' of values not yet closed, innermost last
  bool line_blank_so_far_ = true;  // only blanks since the line began (Normal state)

  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(where_ + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " +
                     what);
  }

  char at(std::size_t k) const { return k < text_.size() ? text_[k] : '\0'; }

  // The code point at i_, checked for UTF-8 and control characters; moves past it.
  CodePoint advance() {
    const CodePoint c = decode(text_, i_);
    if (c.length == 0) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "0x%02X", static_cast<unsigned char>(text_[i_]));
      fail(std::string("invalid UTF-8 (byte ") + buf + "); save the file as UTF-8 text");
    }
    if ((c.value < 0x20 && c.value != '\t' && c.value != '\n' && c.value != '\r') ||
        c.value == 0x7F)
      fail("control character " + hex(c.value) +
           " (TOML allows none but tab and line breaks); remove it");
    i_ += c.length;
    if (c.value == '\n') {
      ++line_, column_ = 1;
      line_blank_so_far_ = true;
    } else {
      ++column_;
    }
    return c;
  }

  // How many times `quote` repeats from i_.
  std::size_t run_of(char quote) const {
    std::size_t k = 0;
    while (at(i_ + k) == quote) ++k;
    return k;
  }

  void step() {
    switch (state_) {
      case State::Normal:
        return normal();
      case State::Comment:
        if (advance().value == '\n') state_ = State::Normal, line_break();
        return;
      case State::Basic:
      case State::Literal:
        return single_line_string();
      case State::MultiBasic:
      case State::MultiLiteral:
        return multi_line_string();
    }
  }

  void line_break() {
    if (open_.empty()) expect_ = Expect::Key, in_key_ = false;  // inside [ ], a value goes on
  }

  void normal() {
    const char c = text_[i_];
    if (static_cast<unsigned char>(c) >= 0x80) {
      const CodePoint cp = decode(text_, i_);
      if (cp.length == 0) advance();  // reports the invalid UTF-8
      fail("character " + hex(cp.value) +
           " outside a string or comment (TOML allows non-ASCII text only in \"strings\" and "
           "after #); quote the value or remove the character");
    }
    if (c == '\n') return advance(), line_break();
    if (c == ' ' || c == '\t' || c == '\r') return void(advance());
    if (c == '#') return state_ = State::Comment, void(advance());
    const bool header = c == '[' && line_blank_so_far_ && open_.empty();
    line_blank_so_far_ = false;
    const Expect before = expect_;
    if (before == Expect::Value && c >= '0' && c <= '9') check_date_time();
    const char innermost = open_.empty() ? '\0' : open_.back();
    expect_ = Expect::Other;
    if ((c == '"' || c == '\'') && before != Expect::Other) {
      const bool multi = run_of(c) >= 3;
      state_ = c == '"' ? (multi ? State::MultiBasic : State::Basic)
                        : (multi ? State::MultiLiteral : State::Literal);
      if (multi) advance(), advance();
      if (before == Expect::Key) in_key_ = true;
    } else if (header) {
      return table_header();
    } else if (c == '[' && before == Expect::Value) {
      open_ += '[', expect_ = Expect::Value;
    } else if (c == '{' && before == Expect::Value) {
      open_ += '{', expect_ = Expect::Key;
    } else if (c == ']' || c == '}') {
      // toml++'s parse_array hands a '}' where a value should be to parse_value, which
      // asserts (Debug) or assumes (Release) that it is not a value terminator.
      if (c == '}' && innermost == '[' && before == Expect::Value)
        fail("'}' where an array expects a value; close the array with ']'");
      if (innermost == (c == ']' ? '[' : '{')) open_.pop_back();
      in_key_ = false;
    } else if (c == '=' && in_key_) {
      expect_ = Expect::Value, in_key_ = false;
    } else if (c == ',') {
      expect_ = innermost == '[' ? Expect::Value : innermost == '{' ? Expect::Key : Expect::Other;
    } else if (c == '.' && in_key_) {
      expect_ = Expect::Key;
    } else if (before == Expect::Key) {
      in_key_ = true;
    }
    advance();
  }

  static bool is_value_terminator(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ']' || c == '}' || c == ',' ||
           c == '#';
  }

  // toml++ reads "YYYY-MM-DD" followed by a space as a date that may go on with a time; when
  // one digit and a terminator follow, it scans on from the terminator, which its
  // TOML_ASSERT_ASSUME(!is_value_terminator) forbids (parser.inl:2636). Never valid TOML.
  void check_date_time() const {
    std::size_t k = i_;
    int count = 0;  // characters as toml++ counts them: '_' is skipped
    char fifth = 0, eighth = 0;
    for (; k < text_.size() && !is_value_terminator(text_[k]); ++k) {
      if (text_[k] == '_') continue;
      if (count == 4) fifth = text_[k];
      if (count == 7) eighth = text_[k];
      ++count;
    }
    if (count == 10 && fifth == '-' && eighth == '-' && at(k) == ' ' && at(k + 1) >= '0' &&
        at(k + 1) <= '9' && k + 2 < text_.size() && is_value_terminator(text_[k + 2]))
      fail(
          "a date followed by a one-digit time; write a time as HH:MM:SS, e.g. "
          "1979-05-27 07:32:00");
  }

  // "[name]" or "[[name]]" at the start of a line: the name must start with a bare-key
  // character or a quote, or toml++'s parse_key() asserts (see toml_guard.h).
  void table_header() {
    advance();  // '['
    const auto skip_blanks = [&] {
      while (at(i_) == ' ' || at(i_) == '\t') advance();
    };
    skip_blanks();
    if (at(i_) == '[') advance();
    skip_blanks();
    if (i_ < text_.size() && at(i_) != ']' && !is_bare_key_start(at(i_)))
      fail("a table name must start with a letter, a digit, _, - or a quote; write e.g. [chain]");
    expect_ = Expect::Key;
  }

  void single_line_string() {
    const char c = text_[i_];
    const bool basic = state_ == State::Basic;
    advance();
    if (c == '\n' || (c == (basic ? '"' : '\''))) {
      state_ = State::Normal;  // closed, or a line break toml++ refuses in this string
      if (c == '\n') line_break();
    } else if (basic && c == '\\' && i_ < text_.size() && text_[i_] != '\n') {
      advance();  // the escaped character: \" does not close the string
    }
  }

  void multi_line_string() {
    const char c = text_[i_];
    const char quote = state_ == State::MultiBasic ? '"' : '\'';
    if (c == quote) {
      const std::size_t k = run_of(quote);
      // Up to two quotes may stand just inside the closing three (TOML 1.0).
      for (std::size_t n = 0; n < std::min<std::size_t>(k, 5); ++n) advance();
      if (k >= 3) state_ = State::Normal;
      return;
    }
    advance();
    if (state_ != State::MultiBasic || c != '\\' || i_ >= text_.size()) return;
    // toml++ asks whether the character after a backslash, and the first one after the blanks
    // that a line-ending backslash skips, is whitespace: non-ASCII there is undefined.
    const char next = text_[i_];
    if (next == ' ' || next == '\t' || next == '\r' || next == '\n') {
      while (at(i_) == ' ' || at(i_) == '\t' || at(i_) == '\r' || at(i_) == '\n') advance();
    }
    if (static_cast<unsigned char>(at(i_)) >= 0x80)
      fail(
          "a non-ASCII character right after a backslash of a \"\"\"string\"\"\" (toml++ 3.3.0 "
          "cannot read it there); put an ASCII character before it");
    if (i_ < text_.size() && next != ' ' && next != '\t' && next != '\r' && next != '\n')
      advance();  // the escaped character: \" does not count as a quote
  }
};

}  // namespace

void check_toml_text(std::string_view text, const std::string& where) {
  Scanner(text, where).run();
}

}  // namespace cb::scene_detail
