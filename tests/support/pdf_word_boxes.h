#pragma once
// The words of a PDF as poppler places them (`pdftotext -bbox-layout`,
// Debian poppler-utils): per page its size and its lines, per line its
// words with their boxes in PostScript points (origin top left). An
// independent reader of what the field report printed, and where.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace rockface::test {

struct PdfWord {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;
  std::string text;
};

struct PdfLine {
  std::vector<PdfWord> words;
  std::string text() const {
    std::string s;
    for (const auto& w : words) s += (s.empty() ? "" : " ") + w.text;
    return s;
  }
};

struct PdfPage {
  double width = 0, height = 0;
  std::vector<PdfLine> lines;
};

inline std::string xml_unescaped(std::string s) {
  static const std::pair<const char*, const char*> entities[] = {{"&lt;", "<"},    {"&gt;", ">"},
                                                                 {"&quot;", "\""}, {"&apos;", "'"},
                                                                 {"&#39;", "'"},   {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1))
      s.replace(at, std::string(from).size(), to);
  return s;
}

// Runs pdftotext on `pdf` (the XHTML written beside it) and reads it back;
// empty when pdftotext fails.
inline std::vector<PdfPage> pdf_word_boxes(const std::filesystem::path& pdf) {
  const std::filesystem::path xhtml = pdf.string() + ".bbox.html";
  const std::string command =
      "pdftotext -bbox-layout '" + pdf.string() + "' '" + xhtml.string() + "'";
  if (std::system(command.c_str()) != 0) return {};
  std::ifstream in(xhtml);
  static const std::regex page_re(R"re(<page width="([0-9.]+)" height="([0-9.]+)")re");
  static const std::regex word_re(
      R"re(<word xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">(.*)</word>)re");
  std::vector<PdfPage> pages;
  std::smatch m;
  for (std::string row; std::getline(in, row);) {
    if (std::regex_search(row, m, page_re)) {
      pages.push_back({std::stod(m[1]), std::stod(m[2]), {}});
    } else if (row.find("<line ") != std::string::npos && !pages.empty()) {
      pages.back().lines.emplace_back();
    } else if (std::regex_search(row, m, word_re) && !pages.empty() &&
               !pages.back().lines.empty()) {
      pages.back().lines.back().words.push_back({std::stod(m[1]), std::stod(m[2]), std::stod(m[3]),
                                                 std::stod(m[4]), xml_unescaped(m[5])});
    }
  }
  return pages;
}

}  // namespace rockface::test
