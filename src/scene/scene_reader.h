// Internal to src/scene: typed, position-aware access to a parsed scene table.
//
// Design note: toml++ keeps the source region of every node and key, so instead of copying
// values into an intermediate struct we read straight from the table and, on any mistake,
// note a problem (scene_problems.h) prefixed with where the offending value came from:
// "file:line:col" of the node (or of its table when the key is missing), or
// "--set KEY=VALUE" when a command-line override put it there. A read that fails answers
// as if the key were absent, so the section readers carry on and every mistake is listed. The
// schema (which keys exist, their types and an example for each) is one table in scene_reader.cpp,
// so unknown-key checks, type errors, overrides and "add e.g. ..." hints cannot disagree with each
// other.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_problems.h"

namespace cb::scene_detail {

// Coefficients: a number, an array of N numbers or a pattern table (chain.mass, chain.stiffness,
// chain.threshold; scene_coefficients.cpp).
enum class Kind { Integer, Number, Bool, String, NumberArray, Coefficients };

struct KeySpec {
  std::string_view section;  // "" for top-level keys
  std::string_view key;
  Kind kind;
  std::string_view example;  // a line the user could paste, e.g. "beads = 30"
};

const KeySpec* find_key_spec(std::string_view section, std::string_view key);

// "did you mean 'gamma'?" and the list of valid names, for an unknown name.
std::string suggest(std::string_view unknown, const std::vector<std::string_view>& valid,
                    std::string_view quote_open = "'", std::string_view quote_close = "'");

// Numbers as the user wrote them (shortest round trip) and computed numbers (4 digits).
std::string format_exact(double v);
std::string format_approx(double v);

class SceneReader {
 public:
  SceneReader(std::string path, toml::table root);

  // Applies one --set after checking its key against the schema; remembers where the
  // value came from so that later errors about it say "--set KEY=VALUE".
  void apply(const Override& o);
  // Unknown sections and keys anywhere in the table, each one noted.
  void check_known_keys();

  bool has_section(std::string_view section) const;
  bool has(std::string_view section, std::string_view key) const;
  // The value's node (nullptr when absent), for values of several shapes (Kind::Coefficients).
  const toml::node* node(std::string_view section, std::string_view key) const;
  // Typed reads: nullopt when absent; a wrong type or a non-finite number is noted as a
  // problem and reads as absent.
  std::optional<double> number(std::string_view section, std::string_view key) const;
  std::optional<std::int64_t> integer(std::string_view section, std::string_view key) const;
  std::optional<bool> boolean(std::string_view section, std::string_view key) const;
  std::optional<std::string> string(std::string_view section, std::string_view key) const;
  std::optional<std::vector<double>> numbers(std::string_view section, std::string_view key) const;

  // Notes "<where section.key is>: <what>" (once per key).
  void fail(std::string_view section, std::string_view key, const std::string& what) const;
  // Notes "<where the section is>: missing key 'k' in [s] <why>; add e.g. <example>", unless
  // the key is present with a problem already noted.
  void fail_missing(std::string_view section, std::string_view key,
                    const std::string& why = {}) const;
  // Notes `what` at a position of the file (a key inside a pattern table).
  void fail_at(std::string_view key, const toml::source_region& at, const std::string& what) const;
  // The section or key already has a problem.
  bool failed(std::string_view section, std::string_view key = {}) const;
  // Required reads: fail_missing and nullopt when absent.
  std::optional<double> require_number(std::string_view section, std::string_view key,
                                       const std::string& why = {}) const;
  std::optional<std::string> require_string(std::string_view section, std::string_view key,
                                            const std::string& why = {}) const;
  // What the type error names for a wrong value, and noting it ("x must be a number, got ...").
  void fail_type(std::string_view section, std::string_view key, const toml::node& n,
                 std::string_view wanted) const;

  Problems& problems() const { return problems_; }
  const std::string& path() const { return path_; }
  // Where every key present came from, and where each section starts (SceneDesc::origins).
  KeyOrigins origins() const;

 private:
  std::string path_;
  toml::table root_;
  std::map<std::string, std::string, std::less<>> origin_;  // "chain.gamma" -> "--set ..."
  mutable Problems problems_;  // reads are const; what they find wrong is not the table's

  // apply()'s checks; fail_here notes a problem and leaves by throwing.
  template <class Fail>
  void apply_checked(const Override& o, const std::string& text, Fail&& fail_here);
  std::string where(std::string_view section, std::string_view key) const;
  std::string section_where(std::string_view section) const;
  std::string position(const toml::source_region& region) const;
};

// "a.b" (or "b" for a top-level key).
std::string dotted(std::string_view section, std::string_view key);

}  // namespace cb::scene_detail
