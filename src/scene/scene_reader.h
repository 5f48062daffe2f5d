// Internal to src/scene: typed, position-aware access to a parsed scene table.
//
// Design note: toml++ keeps the source region of every node and key, so instead of copying
// values into an intermediate struct we read straight from the table and, on any mistake,
// throw SceneError prefixed with where the offending value came from: "file:line:col" of
// the node (or of its table when the key is missing), or "--set KEY=VALUE" when a
// command-line override put it there. The schema (which keys exist, their types and an
// example for each) is one table in scene_reader.cpp, so unknown-key checks, type errors,
// overrides and "add e.g. ..." hints cannot disagree with each other.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace cb::scene_detail {

enum class Kind { Integer, Number, Bool, String, NumberArray };

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
  // Unknown sections and keys anywhere in the table (the first one in file order).
  void check_known_keys() const;

  bool has_section(std::string_view section) const;
  bool has(std::string_view section, std::string_view key) const;
  // Typed reads: nullopt when absent; a wrong type or a non-finite number throws.
  std::optional<double> number(std::string_view section, std::string_view key) const;
  std::optional<std::int64_t> integer(std::string_view section, std::string_view key) const;
  std::optional<bool> boolean(std::string_view section, std::string_view key) const;
  std::optional<std::string> string(std::string_view section, std::string_view key) const;
  std::optional<std::vector<double>> numbers(std::string_view section, std::string_view key) const;

  // Throws SceneError "<where section.key is>: <what>".
  [[noreturn]] void fail(std::string_view section, std::string_view key,
                         const std::string& what) const;
  // Throws "<where the section is>: missing key 'k' in [s] <why>; add e.g. <example>".
  [[noreturn]] void fail_missing(std::string_view section, std::string_view key,
                                 const std::string& why = {}) const;
  // Required reads: fail_missing when absent.
  double require_number(std::string_view section, std::string_view key,
                        const std::string& why = {}) const;
  std::string require_string(std::string_view section, std::string_view key,
                             const std::string& why = {}) const;

  const std::string& path() const { return path_; }
  // Where every key present came from, and where each section starts (SceneDesc::origins).
  KeyOrigins origins() const;

 private:
  std::string path_;
  toml::table root_;
  std::map<std::string, std::string, std::less<>> origin_;  // "chain.gamma" -> "--set ..."

  const toml::node* node(std::string_view section, std::string_view key) const;
  std::string where(std::string_view section, std::string_view key) const;
  std::string section_where(std::string_view section) const;
  std::string position(const toml::source_region& region) const;
  [[noreturn]] void fail_type(std::string_view section, std::string_view key, const toml::node& n,
                              std::string_view wanted) const;
};

}  // namespace cb::scene_detail
