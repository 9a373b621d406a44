#pragma once
// What a reader says when it refuses its input: the one-line message of the
// InputError `parse` throws, "not an InputError: ..." for any other
// exception, or "accepted" when it throws nothing. For the suites that
// assert a refusal's exact words.
#include <exception>
#include <functional>
#include <string>

#include "core/common/error.h"

namespace rockface::test {

inline std::string refusal(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const rockface::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not an InputError: ") + e.what();
  }
  return "accepted";
}

}  // namespace rockface::test
