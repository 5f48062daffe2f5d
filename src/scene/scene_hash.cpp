#include "scene/scene_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace cb {

std::string scene_hash(const std::string& scene_path, const std::vector<Override>& overrides) {
  std::ifstream in(scene_path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  for (const auto& o : overrides) text << '\n' << o.key << '=' << o.value;
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text.str()) h = (h ^ c) * 1099511628211ull;
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace cb
