#pragma once
// A log-in to `rockface office serve` over plain HTTP, as a browser of the
// same origin makes it: for the suite's tests that read the API without
// Chromium.
#include <string>

#include <httplib.h>

namespace rockface::office_web_test {

struct Login {
  int status = 0;
  std::string cookie;  // the session's "name=value" for a Cookie header
  // The known browser's cookie "name=value" when the server gave one
  // (firmware-app/office/known_browsers.h), else "".
  std::string known;
  std::string set_cookie, csrf, error;
};

// `cookie`: a Cookie header to send (e.g. an earlier log-in's `known`).
Login log_in(httplib::Client& c, const std::string& origin, const std::string& role,
             const std::string& password, const std::string& cookie = "");

}  // namespace rockface::office_web_test
