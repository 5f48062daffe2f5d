#include "cluster/merge.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "resources/resources.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

// A shard's files are input like any other (issue #12): refuse a name that is not a regular
// file (a FIFO or /dev/zero would be read forever) or a file larger than `max_bytes`, before
// reading a byte of it.
std::string read_text(const std::string& path, const std::string& what, double max_bytes) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status))
    throw MergeError(path + ": the " + what + " is not a regular file; name the shard's .csv");
  const auto size = fs::file_size(path, ec);
  if (!ec && static_cast<double>(size) > max_bytes)
    throw MergeError(path + ": the " + what + " is " + format_bytes(static_cast<double>(size)) +
                     ", more than the " + format_bytes(max_bytes) +
                     " it can hold; recompute the shard");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw MergeError(path + ": cannot read the " + what +
                     "; check the path (shards are OUT.shards/shard-IIII-of-SSSS.csv, each with "
                     "its .json record)");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first `count` comma-separated fields of `row` as numbers.
bool leading_values(const std::string& row, std::size_t count, std::vector<double>& out) {
  out.clear();
  const char* p = row.data();
  const char* end = row.data() + row.size();
  for (std::size_t k = 0; k < count; ++k) {
    double v = 0;
    const auto r = std::from_chars(p, end, v);
    if (r.ec != std::errc() || r.ptr == end || *r.ptr != ',') return false;
    out.push_back(v);
    p = r.ptr + 1;
  }
  return true;
}

ShardRecord shard_record_of(const std::string& csv_path, const std::string& record_text) {
  try {
    return parse_record(record_text);
  } catch (const std::exception& e) {
    throw MergeError(record_path(csv_path) + ": " + e.what() + "; recompute the shard");
  }
}

}  // namespace

double max_shard_csv_bytes(const ShardRecord& record) {
  const auto columns = std::count(record.header.begin(), record.header.end(), ',') + 1;
  return static_cast<double>(record.header.size() + 1) +
         static_cast<double>(record.points.size()) * csv_row_bytes(static_cast<double>(columns));
}

ShardFile read_shard_file(const std::string& csv_path) {
  const std::string json_path = record_path(csv_path);
  if (!fs::exists(json_path))
    throw MergeError(csv_path + ": no record " + json_path +
                     " beside it, so the shard is unfinished or not from `chainbreak sweep`; "
                     "recompute it (its sweep writes both)");
  const std::string record_text = read_text(json_path, "shard record", kMaxShardRecordBytes);
  // The CSV may hold what its record says and no more: the header, and a row of at most
  // csv_row_bytes per point. The record is parsed twice; it is small next to the CSV.
  const ShardRecord record = shard_record_of(csv_path, record_text);
  return parse_shard_file(csv_path, record_text,
                          read_text(csv_path, "shard CSV", max_shard_csv_bytes(record)));
}

ShardFile parse_shard_file(const std::string& csv_path, const std::string& record_text,
                           const std::string& csv_text) {
  ShardFile f;
  f.csv_path = csv_path;
  f.record = shard_record_of(csv_path, record_text);
  std::istringstream in(csv_text);
  std::string header;
  std::getline(in, header);
  if (header != f.record.header)
    throw MergeError(csv_path + ":1: header '" + header + "' is not '" + f.record.header +
                     "' of its record; recompute the shard");
  // Stops at one row past the record's count: a huge or hostile CSV is refused without
  // holding all of it twice.
  for (std::string row; f.rows.size() <= f.record.points.size() && std::getline(in, row);)
    f.rows.push_back(row);
  if (f.rows.size() != f.record.points.size())
    throw MergeError(csv_path + ": " + (f.rows.size() > f.record.points.size() ? "more" : "fewer") +
                     " rows than its record's points " + std::to_string(f.record.points.first) +
                     " to " + std::to_string(f.record.points.last) + " (" +
                     std::to_string(f.record.points.size()) + "); recompute the shard");
  std::vector<double> values;
  for (std::size_t k = 0; k < f.rows.size(); ++k) {
    const auto expected = f.record.grid.point(f.record.points.first + k);
    if (!leading_values(f.rows[k], expected.size(), values) || values != expected)
      throw MergeError(csv_path + ":" + std::to_string(k + 2) + ": the row is not grid point " +
                       std::to_string(f.record.points.first + k) +
                       " of its record; recompute the shard");
  }
  return f;
}

std::vector<std::string> shard_csvs_in(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".csv" && fs::exists(record_path(e.path().string())))
      out.push_back(e.path().string());
  if (ec) throw MergeError(dir + ": cannot list the folder (" + ec.message() + ")");
  std::sort(out.begin(), out.end());
  return out;
}

Coverage check_coverage(const std::vector<ShardFile>& shards) {
  if (shards.empty()) throw MergeError("no shards to merge; name shard CSVs or their folder");
  for (const auto& s : shards)
    if (const auto why = record_mismatch(shards.front().record, s.record); !why.empty())
      throw MergeError(s.csv_path + " cannot be merged with " + shards.front().csv_path + ": " +
                       why + "; merge only shards of one sweep");
  const std::size_t n = shards.front().record.grid.size();
  std::vector<std::vector<const std::string*>> holders(n);
  for (const auto& s : shards)
    for (std::size_t p = s.record.points.first; p < s.record.points.last; ++p)
      holders[p].push_back(&s.csv_path);
  Coverage c;
  for (std::size_t p = 0; p < n; ++p) {
    if (holders[p].empty()) c.missing.push_back(p);
    if (holders[p].size() > 1) {
      std::vector<std::string> files;
      for (const auto* f : holders[p]) files.push_back(*f);
      c.duplicated.emplace_back(p, files);
    }
  }
  return c;
}

std::string merged_csv(const std::vector<ShardFile>& shards) {
  std::vector<const ShardFile*> order;
  for (const auto& s : shards) order.push_back(&s);
  std::sort(order.begin(), order.end(), [](const ShardFile* a, const ShardFile* b) {
    return a->record.points.first < b->record.points.first;
  });
  std::string text = shards.front().record.header + "\n";
  for (const auto* s : order)
    for (const auto& row : s->rows) text += row + "\n";
  return text;
}

std::string merged_json(const std::vector<ShardFile>& shards, const std::string& version) {
  using json = nlohmann::ordered_json;
  const auto& r = shards.front().record;
  json j = json::parse(record_json(r));
  for (const char* k :
       {"shard", "first_point", "end_point", "wall_seconds", "peak_memory_kib", "host"})
    j.erase(k);
  j["chainbreak_version"] = version;
  json list = json::array();
  double wall = 0;
  for (const auto& s : shards) {
    list.push_back({{"file", s.csv_path},
                    {"shard", {{"index", s.record.shard.index}, {"count", s.record.shard.count}}},
                    {"first_point", s.record.points.first},
                    {"end_point", s.record.points.last},
                    {"wall_seconds", s.record.wall_seconds},
                    {"peak_memory_kib", s.record.peak_memory_kib},
                    {"host", s.record.host},
                    {"chainbreak_version", s.record.version}});
    wall += s.record.wall_seconds;
  }
  j["shards"] = list;
  j["shard_wall_seconds_total"] = wall;
  return j.dump(1) + "\n";
}

std::string index_ranges(const std::vector<std::size_t>& v) {
  std::string out;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i;
    while (j + 1 < v.size() && v[j + 1] == v[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(v[i]);
    if (j > i) out += "-" + std::to_string(v[j]);
    i = j + 1;
  }
  return out;
}

std::vector<std::size_t> shards_holding(std::size_t n, std::size_t shards,
                                        const std::vector<std::size_t>& points) {
  std::vector<std::size_t> out;
  for (std::size_t p : points) {
    const std::size_t s = shard_of_point(n, shards, p);
    if (out.empty() || out.back() != s) out.push_back(s);
  }
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace cb
