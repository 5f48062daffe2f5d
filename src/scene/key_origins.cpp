#include "scene/scene.h"

#include <stdexcept>

namespace cb {

KeyOrigins::KeyOrigins(Map read) : read_(std::make_shared<const Map>(std::move(read))) {}

const std::string* KeyOrigins::find(std::string_view key) const {
  for (const auto& [k, where] : set_)
    if (k == key) return &where;
  if (read_)
    if (auto it = read_->find(key); it != read_->end()) return &it->second;
  return nullptr;
}

const std::string& KeyOrigins::at(std::string_view key) const {
  if (const std::string* where = find(key)) return *where;
  throw std::out_of_range("no origin for " + std::string(key));
}

void KeyOrigins::set(const std::string& key, const std::string& where) {
  for (auto& [k, w] : set_)
    if (k == key) {
      w = where;
      return;
    }
  set_.emplace_back(key, where);
}

}  // namespace cb
