#include "mpm/scene/scene_error.hpp"

#include <utility>

namespace mpm {

SceneError::SceneError(SourceLocation where_, std::string key_, std::string message_)
    : std::runtime_error(format(where_, key_, message_)),
      where(std::move(where_)),
      key(std::move(key_)),
      message(std::move(message_)) {}

std::string SceneError::format(const SourceLocation& where, const std::string& key, const std::string& message) {
  std::string text = where.file;
  if (where.line > 0) {
    text += ':' + std::to_string(where.line) + ':' + std::to_string(where.column > 0 ? where.column : 1);
  }
  if (!key.empty()) text += ": " + key;
  text += ": " + message;
  return text;
}

}  // namespace mpm
