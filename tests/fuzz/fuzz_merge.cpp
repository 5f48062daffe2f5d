// `merge`'s inputs: shard records (JSON) and shard CSVs, read as merge reads a folder of them
// (parse_shard_file), then checked against each other and merged (check_coverage,
// merged_csv, merged_json). The input holds one or two shards, each "RECORD\n%%\nCSV", the
// two apart by "\n%%%%\n" (make_seeds.py writes them so).
// Invariants: a shard that reads has exactly its record's rows; two shards that merge give
// one header line plus every row of both, and a complete coverage has each point once.
#include <string_view>

#include "cluster/merge.h"
#include "fuzz_support.h"

namespace {

// Splits at the first `sep`; without one, everything is `head` and `tail` is empty.
void split(std::string_view text, std::string_view sep, std::string& head, std::string& tail) {
  const auto at = text.find(sep);
  head = std::string(text.substr(0, at));
  tail = at == std::string_view::npos ? std::string() : std::string(text.substr(at + sep.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = cb::fuzz::text_of(data, size);
  std::string first, second;
  split(text, "\n%%%%\n", first, second);
  std::vector<cb::ShardFile> shards;
  for (const std::string* part : {&first, &second}) {
    if (part->empty()) continue;
    std::string record, csv;
    split(*part, "\n%%\n", record, csv);
    try {
      shards.push_back(cb::parse_shard_file("shard.csv", record, csv));
    } catch (const cb::MergeError&) {
      return 0;
    }
    FUZZ_CHECK(shards.back().rows.size() == shards.back().record.points.size());
  }
  if (shards.empty()) return 0;
  cb::Coverage coverage;
  try {
    coverage = cb::check_coverage(shards);
  } catch (const cb::MergeError&) {
    return 0;
  }
  const std::size_t n = shards.front().record.grid.size();
  FUZZ_CHECK(coverage.missing.size() <= n);
  for (std::size_t p : coverage.missing) FUZZ_CHECK(p < n);
  // What merge prints for the missing points: the ranges and the shards to recompute.
  (void)cb::index_ranges(coverage.missing);
  (void)cb::shards_holding(n, shards.front().record.shard.count, coverage.missing);
  if (!coverage.complete()) return 0;
  std::size_t rows = 0;
  for (const auto& s : shards) rows += s.rows.size();
  FUZZ_CHECK(rows == n);
  const std::string merged = cb::merged_csv(shards);
  std::size_t lines = 0;
  for (char c : merged) lines += c == '\n';
  // A row may itself hold no '\n' (getline split there), so lines = header + rows.
  FUZZ_CHECK(lines == rows + 1);
  (void)cb::merged_json(shards, "fuzz");
  return 0;
}
