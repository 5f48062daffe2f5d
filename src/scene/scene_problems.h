// Internal to src/scene: the mistakes of one scene, collected and reported together.
//
// Design note: a compiler lists every error of a file, not the first; a scene with three
// mistakes should cost one edit-run cycle, not three (issue #21). The reader and validate()
// therefore add each problem here and carry on with a harmless value; parse_scene throws one
// SceneError with every message, in file order. One message per key: once a key (or its
// whole section) is wrong, later checks that would only repeat it, or that read its stand-in
// value, stay silent (failed()).
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace cb::scene_detail {

class Problems {
 public:
  // key: "chain.beads", a section "chain", or "" for the file as a whole. where: where the
  // value came from ("file:line:col", "--set K=V"), or "" for a scene built in memory.
  void add(std::string_view key, const std::string& where, const std::string& what);
  // The key, or its section, already has a problem.
  bool failed(std::string_view key) const;
  bool empty() const { return problems_.empty(); }
  // "where: what" each, positions in the file first by line and column, then the others
  // (--set, in memory) in the order they were found.
  std::vector<std::string> messages() const;
  // SceneError with every message, one per line; nothing when there is none.
  void throw_if_any() const;

 private:
  struct Problem {
    std::string where, what;
  };
  std::vector<Problem> problems_;
  std::set<std::string, std::less<>> failed_;
};

}  // namespace cb::scene_detail
