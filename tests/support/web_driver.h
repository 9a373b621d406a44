#pragma once
// A small WebDriver client (W3C protocol, plain HTTP JSON) driving Debian's
// headless Chromium through chromedriver: real clicks, typing, drags,
// scripts and screenshots for the office web suite.
#include <sys/types.h>

#include <chrono>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

namespace httplib {
class Client;
}

namespace rockface::office_web_test {

class WebDriver {
 public:
  // Whether /usr/bin/chromium and /usr/bin/chromedriver are installed.
  static bool available();

  // Starts chromedriver on a free loopback port and a headless Chromium
  // with a window of that size (CSS pixels).
  WebDriver(int width, int height);
  ~WebDriver();
  WebDriver(const WebDriver&) = delete;
  WebDriver& operator=(const WebDriver&) = delete;

  void go(const std::string& url);
  // The element matching a CSS selector, waiting up to `wait` for it;
  // throws naming the selector when it does not come.
  std::string wait_for(const std::string& css,
                       std::chrono::milliseconds wait = std::chrono::seconds(20));
  void click(const std::string& element);
  void type(const std::string& element, const std::string& text);
  // Runs a script (its `return` value comes back); arguments in `args`.
  nlohmann::json script(const std::string& body,
                        const nlohmann::json& args = nlohmann::json::array());
  // A script returning an element: its reference for click().
  std::string element_by_script(const std::string& body);
  // Presses the mouse on the element's centre, moves by (dx, dy), releases.
  void drag(const std::string& element, int dx, int dy);
  cv::Mat screenshot();  // BGR, device pixels
  std::string cookie(const std::string& name);
  // Whether the page opened an alert (a script that should not have run).
  bool alert_open();

 private:
  nlohmann::json call(const std::string& method, const std::string& path,
                      const nlohmann::json& body = nullptr);

  pid_t pid_ = -1;
  int port_ = 0;
  std::string session_;
  std::unique_ptr<httplib::Client> http_;
};

}  // namespace rockface::office_web_test
