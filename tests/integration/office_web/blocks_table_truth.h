#pragma once
// The visit page's blocks table (issue 46: "the blocks with verdict, margin,
// mode, FoS and motion after failure") checked against the blocks of the
// visit's latest analysis as the tablet stored them in its own project
// file, read with SQLite, not through the office's server or pages.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace rockface::office_web_test {

// `rows`: the page's table.blocks rows, each cell's text (Block, Verdict,
// Margin, Mode, FoS, Volume, Mass, Rotation, After failure). `name` leads
// each failure's message.
void expect_blocks_table(const nlohmann::json& rows, const std::filesystem::path& project,
                         std::int64_t visit_id, const std::string& name);

}  // namespace rockface::office_web_test
