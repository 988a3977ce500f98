// The font of the labels the tools draw into their images (OpenImageIO's render_text).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace kutlog::tools {

// As a full path: OIIO 2.4 opens it directly instead of searching its font directories.
// std::runtime_error naming the Debian package if it is missing.
inline const char* label_font() {
  static constexpr const char* kPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (!std::filesystem::exists(kPath))
    throw std::runtime_error(std::string("font ") + kPath +
                             " is missing (Debian package fonts-dejavu-core)");
  return kPath;
}

}  // namespace kutlog::tools
