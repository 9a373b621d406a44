#pragma once
// A JSON file read whole or written (two-space indent), as the suites that
// hand picks files to `rockface measure` and read its MEASURES.json do.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace rockface::test {

inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline void write_json(const std::filesystem::path& p, const nlohmann::json& j) {
  std::ofstream(p) << j.dump(2);
}

}  // namespace rockface::test
