#include "storage/exchange/ptx_reader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/common/error.h"

namespace rockface::storage {

namespace ptx_detail {

// The file line by line, each split into numbers.
class PtxLines {
 public:
  PtxLines(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  bool at_end() {
    while (pos_ < bytes_.size() && (bytes_[pos_] == '\n' || bytes_[pos_] == '\r' ||
                                    bytes_[pos_] == ' ' || bytes_[pos_] == '\t'))
      line_no_ += bytes_[pos_++] == '\n';
    return pos_ >= bytes_.size();
  }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  std::string where() const { return "line " + std::to_string(line_no_ + 1); }

  // The next line's numbers; `what` names the line in errors.
  const std::vector<double>& next(const std::string& what) {
    if (at_end()) throw InputError(source_, where() + ": the file ends before " + what);
    std::size_t nl = bytes_.find('\n', pos_);
    if (nl == std::string_view::npos) nl = bytes_.size();
    const std::string_view line = bytes_.substr(pos_, nl - pos_);
    values_.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      if (i == start) break;
      double v = 0;
      const auto [end, ec] = std::from_chars(line.data() + start, line.data() + i, v);
      if (ec != std::errc() || end != line.data() + i || !std::isfinite(v))
        throw InputError(source_,
                         where() + " (" + what + "): '" +
                             std::string(line.substr(start, std::min<std::size_t>(i - start, 40))) +
                             "' is not a finite number");
      values_.push_back(v);
    }
    pos_ = nl + 1;
    ++line_no_;
    return values_;
  }

  // The next line as exactly `n` numbers.
  const std::vector<double>& exactly(std::size_t n, const std::string& what) {
    const std::size_t line = line_no_;
    const auto& v = next(what);
    if (v.size() != n)
      throw InputError(source_, "line " + std::to_string(line + 1) + " (" + what +
                                    "): " + std::to_string(v.size()) + " values, " +
                                    std::to_string(n) + " expected");
    return v;
  }

 private:
  std::string_view bytes_;
  const std::string& source_;
  std::size_t pos_ = 0, line_no_ = 0;
  std::vector<double> values_;
};

}  // namespace ptx_detail

ImportedSurface parse_ptx(std::string_view bytes, const std::string& source) {
  ptx_detail::PtxLines lines(bytes, source);
  ImportedSurface out;
  out.format = "PTX";
  int scan = 0;
  bool coloured = false;
  while (!lines.at_end()) {
    ++scan;
    const std::string name = "scan " + std::to_string(scan);
    const double columns = lines.exactly(1, name + "'s column count")[0];
    const double rows = lines.exactly(1, name + "'s row count")[0];
    for (double n : {columns, rows})
      if (n < 0 || n != std::floor(n))
        throw InputError(source, name + ": a count is not a whole number");
    // A point takes at least eight characters ("0 0 0 0\n").
    const double points = columns * rows;
    if (points > static_cast<double>(lines.remaining()) / 8 + 1)
      throw InputError(source, name + ": " + std::to_string(static_cast<std::uint64_t>(columns)) +
                                   " x " + std::to_string(static_cast<std::uint64_t>(rows)) +
                                   " points do not fit in the file's remaining " +
                                   std::to_string(lines.remaining()) + " bytes");
    const auto& position_line = lines.exactly(3, name + "'s scanner position");
    const Eigen::Vector3d position(position_line[0], position_line[1], position_line[2]);
    for (int k = 0; k < 3; ++k) lines.exactly(3, name + "'s scanner axis");
    Eigen::Matrix4d m;
    for (int i = 0; i < 4; ++i) {
      const auto& row = lines.exactly(4, name + "'s registration matrix");
      for (int k = 0; k < 4; ++k) m(i, k) = row[static_cast<std::size_t>(k)];
    }
    // PTX writes the matrix for row vectors: p' = p * M, translation last row.
    const Eigen::Matrix3d R = m.topLeftCorner<3, 3>().transpose();
    const Eigen::Vector3d t = m.block<1, 3>(3, 0).transpose();
    // The header's position is the scanner's, registered (the matrix's
    // translation, written again); an export that left it 0 0 0 has the
    // scanner's origin registered by the matrix: its translation.
    out.scanner_positions.push_back(position.isZero() ? t : position);
    const auto count = static_cast<std::uint64_t>(points);
    out.mesh.vertices.reserve(out.mesh.vertices.size() + count);
    for (std::uint64_t n = 0; n < count; ++n) {
      const std::string what = name + " point " + std::to_string(n);
      const auto& v = lines.next(what);
      if (v.size() != 4 && v.size() != 7)
        throw InputError(source, what + ": " + std::to_string(v.size()) +
                                     " values (x y z intensity, then r g b or nothing)");
      if (scan == 1 && n == 0) coloured = v.size() == 7;
      if (coloured != (v.size() == 7))
        throw InputError(source, what + ": colours on some points and not on others");
      const Eigen::Vector3d p(v[0], v[1], v[2]);
      if (p.isZero()) {  // no return in this direction
        ++out.skipped_points;
        continue;
      }
      out.mesh.vertices.push_back(R * p + t);
      // Without colours the intensity is the picture (intensity_grey.h).
      if (!coloured) out.intensities.push_back(static_cast<float>(v[3]));
      if (coloured) {
        std::array<std::uint8_t, 3> c{};
        for (std::size_t k = 0; k < 3; ++k) {
          if (v[4 + k] < 0 || v[4 + k] > 255)
            throw InputError(source, what + ": a colour value outside 0..255");
          c[k] = static_cast<std::uint8_t>(std::lround(v[4 + k]));
        }
        out.mesh.colours.push_back(c);
      }
    }
  }
  if (scan == 0) throw InputError(source, "no scan in the file");
  if (out.mesh.vertices.empty()) throw InputError(source, "no point with a return in the file");
  take_datum(out);
  return out;
}

}  // namespace rockface::storage
