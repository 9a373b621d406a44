#pragma once
// Walks a JSON document keeping the field path for messages: every rejection
// names the file and the field ("traces[2].pixels[1][0]: must be finite").
// Shared by the scene and the picks parsers.
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "core/common/error.h"

namespace rockface::storage {

// The bare tokens some writers put for non-finite numbers (Python's json:
// NaN, Infinity, -Infinity).
inline bool is_non_finite_token(const std::string& s) {
  return s == "NaN" || s == "-NaN" || s == "Infinity" || s == "-Infinity";
}

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
    throw InputError(where(path), reason);
  }
  // How a rejection names the field: the file, then the field path.
  std::string where(const std::string& path) const { return source_ + ": " + path; }

  const nlohmann::json& require(const nlohmann::json& obj, const std::string& path,
                                const char* key) const {
    if (!obj.is_object()) fail(path, "must be an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing");
    return *it;
  }
  const nlohmann::json* optional(const nlohmann::json& obj, const std::string& path,
                                 const char* key) const {
    if (!obj.is_object()) fail(path, "must be an object");
    auto it = obj.find(key);
    return (it == obj.end() || it->is_null()) ? nullptr : &*it;
  }

  double number(const nlohmann::json& v, const std::string& path) const {
    if (v.is_string() && is_non_finite_token(v.get<std::string>()))
      fail(path, "must be finite, not " + v.get<std::string>());
    if (v.is_null()) fail(path, "must be a number, not null (a NaN written by a JSON writer?)");
    if (!v.is_number()) fail(path, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "must be finite");
    return d;
  }
  double number_in(const nlohmann::json& v, const std::string& path, double lo, double hi,
                   bool hi_open = false) const {
    const double d = number(v, path);
    if (d < lo || d > hi || (hi_open && d == hi)) {
      std::ostringstream msg;
      msg << v.dump() << " is outside [" << lo << ", " << hi << (hi_open ? ")" : "]");
      fail(path, msg.str());
    }
    return d;
  }
  double positive(const nlohmann::json& v, const std::string& path) const {
    const double d = number(v, path);
    if (!(d > 0)) fail(path, v.dump() + " must be positive");
    return d;
  }
  double non_negative(const nlohmann::json& v, const std::string& path) const {
    const double d = number(v, path);
    if (d < 0) fail(path, v.dump() + " must not be negative");
    return d;
  }
  int integer(const nlohmann::json& v, const std::string& path) const {
    if (!v.is_number_integer()) fail(path, "must be a whole number");
    return v.get<int>();
  }
  bool boolean(const nlohmann::json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, "must be true or false");
    return v.get<bool>();
  }
  std::string string(const nlohmann::json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "must be a string");
    std::string s = v.get<std::string>();
    // A NUL cut every message that quoted the text ("rockface: abc") and
    // every C string the text reached (issue 41).
    if (s.find('\0') != std::string::npos)
      fail(path, "contains a NUL character (\\u0000 at byte " + std::to_string(s.find('\0')) +
                     "), which is not allowed in a name or a text");
    return s;
  }
  std::string id(const nlohmann::json& v, const std::string& path) const {
    std::string s = string(v, path);
    if (s.empty()) fail(path, "must not be empty");
    return s;
  }
  Eigen::Vector3d vec3(const nlohmann::json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) fail(path, "must be an array of 3 numbers");
    return {number(v[0], path + "[0]"), number(v[1], path + "[1]"), number(v[2], path + "[2]")};
  }
  const nlohmann::json& array(const nlohmann::json& v, const std::string& path) const {
    if (!v.is_array()) fail(path, "must be an array");
    return v;
  }
  // Refuses a key of `obj` that is not in `known` by its path, listing the
  // known ones: a misspelt key ("bond_strenght") is said, never ignored.
  void only_fields(const nlohmann::json& obj, const std::string& path,
                   std::initializer_list<const char*> known) const {
    if (!obj.is_object()) fail(path, "must be an object");
    for (const auto& item : obj.items()) {
      bool ok = false;
      for (const char* k : known) ok = ok || item.key() == k;
      if (ok) continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(join(path, item.key().c_str()), "unknown field (" + list + ")");
    }
  }
  static std::string join(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }
  static std::string index(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

 private:
  std::string source_;
};

// The first number in `text` beyond double's range (1e309): its field path
// ("joints[0].dip"), line, column and token. nlohmann refuses such a number
// (out_of_range.406) without saying where, so the text (valid JSON up to
// that number) is walked again, keeping the path.
struct NumberOverflow {
  std::string path, token;
  std::size_t line = 0, column = 0;
};

inline std::optional<NumberOverflow> find_number_overflow(const std::string& text) {
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
  };
  std::vector<Frame> stack;
  bool expect_key = false;
  std::size_t line = 1, column = 1;
  auto path = [&] {
    std::string out;
    for (const auto& f : stack)
      out += f.array ? "[" + std::to_string(f.index) + "]" : (out.empty() ? "" : ".") + f.key;
    return out.empty() ? std::string("(top level)") : out;
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"') {  // a string: a key where one is expected, else a value
      std::string s;
      std::size_t j = i + 1;
      for (; j < text.size() && text[j] != '"'; ++j) {
        if (text[j] == '\\' && j + 1 < text.size()) s += text[j++];
        s += text[j];
      }
      if (expect_key && !stack.empty() && !stack.back().array) {
        stack.back().key = s;
        expect_key = false;
      }
      column += j + 1 - i;  // a JSON string holds no raw line break
      i = j + 1;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i + 1;
      while (end < text.size() &&
             std::string_view("0123456789.eE+-").find(text[end]) != std::string_view::npos)
        ++end;
      const std::string token = text.substr(i, end - i);
      if (!std::isfinite(std::strtod(token.c_str(), nullptr)))
        return NumberOverflow{path(), token, line, column};
      column += end - i;
      i = end;
      continue;
    }
    if (c == '{' || c == '[') {
      stack.push_back({c == '[', 0, ""});
      expect_key = c == '{';
    } else if ((c == '}' || c == ']') && !stack.empty()) {
      stack.pop_back();
    } else if (c == ',' && !stack.empty()) {
      if (stack.back().array)
        ++stack.back().index;
      else
        expect_key = true;
    }
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    ++i;
  }
  return std::nullopt;
}

// A number beyond double's range in `text` (nlohmann's bare out_of_range.406)
// as bad input naming the file, the field and where: "FILE: joints[0].dip:
// 1e309 is beyond the range of a number (about 1.8e308; line 3, column 12)".
[[noreturn]] inline void throw_number_overflow(const std::string& text, const std::string& source) {
  const auto at = find_number_overflow(text);
  if (!at) throw InputError(source, "a number is beyond double's range (about 1.8e308)");
  throw InputError(source + ": " + at->path,
                   at->token + " is beyond the range of a number (about 1.8e308; line " +
                       std::to_string(at->line) + ", column " + std::to_string(at->column) + ")");
}

// Parses JSON text, reading bare NaN / Infinity tokens as strings so that
// Reader::number rejects them naming the field, not as a syntax error at a
// byte offset. Throws InputError(source, ...) for text that is not JSON.
inline nlohmann::json parse_json_naming_nan(const std::string& text, const std::string& source) {
  std::string quoted;
  quoted.reserve(text.size() + 16);
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      quoted += c;
      if (c == '\\' && i + 1 < text.size())
        quoted += text[++i];
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    bool replaced = false;
    for (const char* token : {"-Infinity", "Infinity", "-NaN", "NaN"}) {
      const std::string t(token);
      if (text.compare(i, t.size(), t) == 0) {
        quoted += '"' + t + '"';
        i += t.size() - 1;
        replaced = true;
        break;
      }
    }
    if (!replaced) quoted += c;
  }
  try {
    return nlohmann::json::parse(quoted);
  } catch (const nlohmann::json::out_of_range&) {
    throw_number_overflow(text, source);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, std::string("not valid JSON (") + e.what() + ")");
  }
}

}  // namespace rockface::storage
