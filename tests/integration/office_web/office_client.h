#pragma once
// A log-in to `rockface office serve` over plain HTTP, as a browser of the
// same origin makes it: for the suite's tests that read the API without
// Chromium.
#include <string>

#include <httplib.h>

namespace rockface::office_web_test {

struct Login {
  int status = 0;
  std::string cookie;  // "name=value" for a Cookie header
  std::string set_cookie, csrf, error;
};

Login log_in(httplib::Client& c, const std::string& origin, const std::string& role,
             const std::string& password);

}  // namespace rockface::office_web_test
