// The guard before toml++ (src/scene/toml_guard.h): issue #12's rows 7 and 8 stay regression
// tests, text toml++ 3.3.0 cannot read safely is refused with a position, and valid TOML with
// non-ASCII text in strings and comments still reads. The fuzz build (tests/fuzz, toml++
// compiled in with asserts and UBSan) shows the undefined behaviour these inputs reach
// without the guard.
#include <catch2/catch.hpp>
#include <string>

#include "scene/scene.h"
#include "scene/toml_guard.h"
#include "scene_test_support.h"

using Catch::Matchers::Contains;
using cb::scene_detail::check_toml_text;
using namespace cb::scene_test;

namespace {

std::string guard_error(const std::string& text) {
  try {
    check_toml_text(text, "g.toml");
  } catch (const cb::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("issue 12 row 7: a non-ASCII character after a key is refused before toml++",
          "[scene][hostile]") {
  // The fuzzer's input, base64 dGnvu7sgPSABAAQAAAAAACJ4IgoieCIKW2NoYWlbY2hhaQp0eXBlbXAiCg==:
  // "ti" U+FEFB " = " and control characters; U+FEFB lies in a bucket of
  // is_non_ascii_horizontal_whitespace that ends in __builtin_unreachable.
  const std::string row7(
      "ti\xEF\xBB\xBB = \x01\x00\x04\x00\x00\x00\x00\x00\"x\"\n\"x\"\n"
      "[chai[chai\ntypemp\"\n",
      43);
  REQUIRE(row7.size() == 43);
  CHECK_THAT(error_of(row7), Contains("t.toml:1:3: character U+FEFB outside a string or comment"));
  // The same code point inside a string is fine for toml++ and for TOML.
  CHECK(error_of("title = \"ti\xEF\xBB\xBB\"\n" + kBase) == "(no error)");
}

TEST_CASE("issue 12 row 7: the --set value of an unclosed array with U+0385 is read as text, not by toml++",
          "[scene][hostile]") {
  // base64 ZHJpdmUudGltZXM9WzEuMCwgzoVpdgI=
  const std::string text = "drive.times=[1.0, \xCE\x85iv\x02";
  const cb::Override o = cb::parse_override(text);
  const std::string e = error_of(with("type = \"ramp\"", "type = \"impulses\""), {o});
  CHECK_THAT(e, Contains("--set " + text));
  CHECK_THAT(e, Contains("drive.times must be"));
}

TEST_CASE("issue 12 row 8: a table name that starts with '.' is refused before toml++",
          "[scene][hostile]") {
  // toml++'s parse_table_header calls parse_key, which asserts (Debug) or assumes (Release)
  // that a key starts with a bare-key character or a quote.
  const std::string e = error_of(with("[chain]", "[.hain]"));
  CHECK_THAT(e, Contains("t.toml:1:2: a table name must start with a letter"));
  CHECK_THAT(guard_error("[[ .x]]\n"), Contains("g.toml:1:4: a table name must start"));
  CHECK_THAT(guard_error("  [=]\n"), Contains("g.toml:1:4:"));
  // An array of arrays whose inner line starts with '[' is a value, not a table header.
  CHECK(guard_error("a = [\n  [+1],\n  [#c\n  2]]\n") == "(no error)");
  CHECK(guard_error("[\"quoted\"]\n['lit']\n[_a-1]\n[ b ]\n") == "(no error)");
}

TEST_CASE("non-ASCII text stays allowed in strings and comments", "[scene][hostile]") {
  // U+00FC and U+03C4 fall in bucket 0 of toml++'s whitespace table, U+3001 in bucket 11.
  const std::string title =
      "Kettenbr\xC3\xBC"
      "che, \xCF\x84 \xE3\x80\x81";
  const cb::SceneDesc s = parse_scene("title = \"" + title + "\"  # \xCF\x84\n" + kBase, "t.toml");
  CHECK(s.title == title);
  CHECK(guard_error("a = 'l\xC3\xA9'\nb = \"\"\"x\n\xC3\xA9\"\"\"\nc = '''\xC3\xA9'''\n") ==
        "(no error)");
  CHECK(guard_error("\xEF\xBB\xBF"
                    "a = 1\n") == "(no error)");  // a byte order mark
  // Up to two quotes just inside the closing ones belong to the string (TOML 1.0).
  CHECK_THAT(guard_error("a = \"\"\"x\"\"\"\"\xC3\xA9\"\"\"\n"),
             Contains("g.toml:1:13: character U+00E9 outside"));
}

TEST_CASE("the guard refuses what toml++ cannot read safely, with a position", "[scene][hostile]") {
  CHECK_THAT(guard_error("a = 1\xC3\xA9\n"), Contains("g.toml:1:6: character U+00E9 outside"));
  CHECK_THAT(guard_error("a = [\xE3\x80\x81]\n"), Contains("g.toml:1:6: character U+3001 outside"));
  CHECK_THAT(guard_error("a = 1\nb = \xC3\n"), Contains("g.toml:2:5: invalid UTF-8 (byte 0xC3)"));
  CHECK_THAT(guard_error("a = \"\xED\xA0\x80\"\n"), Contains("invalid UTF-8"));  // a surrogate
  CHECK_THAT(guard_error("a = \"\xC0\xAF\"\n"), Contains("invalid UTF-8"));      // overlong '/'
  CHECK_THAT(guard_error("a = \"x\x7F\"\n"), Contains("g.toml:1:7: control character U+007F"));
  CHECK_THAT(guard_error("# \x01\n"), Contains("g.toml:1:3: control character U+0001"));
  // In a """string""", toml++ asks "whitespace?" of the character after a backslash and of
  // the first one after the blanks a line-ending backslash skips.
  CHECK_THAT(guard_error("a = \"\"\"x\\\n   \xC3\xA9\"\"\"\n"),
             Contains("g.toml:2:4: a non-ASCII character right after a backslash"));
  CHECK_THAT(guard_error("a = \"\"\"\\\xC3\xA9\"\"\"\n"), Contains("right after a backslash"));
  CHECK(guard_error("a = \"\"\"x\\\n   y\xC3\xA9\"\"\"\n") == "(no error)");
  CHECK(guard_error("a = \"\\\"\xC3\xA9\"\n") == "(no error)");  // \" does not close it
}

TEST_CASE("fuzz findings: '}' where an array expects a value", "[scene][hostile]") {
  // tests/fuzz/corpus/fuzz_scene/crash_toml_array_brace: parse_array hands '}' to
  // parse_value, whose TOML_ASSERT_ASSUME(!is_value_terminator) fails (parser.inl:2549).
  CHECK_THAT(error_of(with("gamma = 0.0", "gamma = [[}")),
             Contains("t.toml:3:11: '}' where an array expects a value"));
  CHECK_THAT(guard_error("a = [1,\n # c\n }\n"), Contains("g.toml:3:2: '}' where an array"));
  CHECK(guard_error("a = [{b = 1}, {}]\nc = {d = [1], e = {}}\n") == "(no error)");
}

TEST_CASE("fuzz findings: a quote inside a bare value does not open a string", "[scene][hostile]") {
  // tests/fuzz/corpus/fuzz_set/crash_quote_in_number: --set chain.gamma=0'U+FEFEain00. toml++
  // reads "0'..." as one bare value up to a terminator, asking "whitespace?" of U+FEFE.
  CHECK_THAT(guard_error("v = 0'\xEF\xBB\xBE"
                         "ain00"),
             Contains("g.toml:1:7: character U+FEFE outside a string"));
  const std::string e = error_of(kBase, {cb::parse_override("chain.gamma=0'\xEF\xBB\xBE"
                                                            "ain00")});
  CHECK_THAT(e, Contains("chain.gamma must be a number"));
  // Where a key or a value begins, a quote does open one.
  CHECK(guard_error(
            "\"k\xC3\xA9\" = 1\na.'b\xC3\xA9' = 2\n[t . \"\xC3\xA9\"]\nc = [\n'\xC3\xA9']\n") ==
        "(no error)");
  // tests/fuzz/corpus/fuzz_set/crash_equals_in_bare_value: "=", "[" and "{" inside a bare
  // value do not begin a value either.
  CHECK_THAT(guard_error("v = 2hain.gmma='\xEF\xBB\xBE"
                         "ain00e=-"),
             Contains("g.toml:1:17: character U+FEFE outside"));
  CHECK_THAT(guard_error("v = 2['\xC3\xA9']"), Contains("g.toml:1:8: character U+00E9 outside"));
  CHECK_THAT(guard_error("v = 2{'\xC3\xA9'}"), Contains("g.toml:1:8: character U+00E9 outside"));
}

TEST_CASE("fuzz findings: a date followed by a one-digit time", "[scene][hostile]") {
  // tests/fuzz/corpus/fuzz_scene/crash_date_one_digit: toml++ scans on from the terminator
  // after "0000-82-'s 0" and fails TOML_ASSERT_ASSUME(!is_value_terminator) (parser.inl:2636).
  CHECK_THAT(guard_error("s = 0000-82-'s 0,00-- \n"),
             Contains("g.toml:1:5: a date followed by a one-digit time"));
  CHECK_THAT(guard_error("d = [1979-05-27 7]\n"), Contains("g.toml:1:6: a date followed"));
  CHECK(guard_error("d = 1979-05-27 07:32:00\ne = 1979-05-27\nf = 1979-05-27 7") == "(no error)");
}
