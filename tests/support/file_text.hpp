// A test's file as text, read and written whole, byte for byte (no newline conversion).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stickslip {

inline std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void Spit(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace stickslip
