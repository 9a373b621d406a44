#include "tests/support/web_driver.h"

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include <httplib.h>

namespace rockface::office_web_test {

using nlohmann::json;

namespace {

constexpr const char* kElement = "element-6066-11e4-a52e-4f735466cecf";

int free_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t n = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &n);
  ::close(s);
  return ntohs(a.sin_port);
}

std::vector<std::uint8_t> base64_decode(const std::string& in) {
  static const std::string chars =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  int value = 0, bits = -8;
  for (char ch : in) {
    const std::size_t d = chars.find(ch);
    if (d == std::string::npos) continue;
    value = (value << 6) + static_cast<int>(d);
    bits += 6;
    if (bits >= 0) {
      out.push_back(static_cast<std::uint8_t>((value >> bits) & 0xff));
      bits -= 8;
    }
  }
  return out;
}

}  // namespace

bool WebDriver::available() {
  return std::filesystem::exists("/usr/bin/chromium") &&
         std::filesystem::exists("/usr/bin/chromedriver");
}

WebDriver::WebDriver(int width, int height) {
  port_ = free_port();
  const std::string port_arg = "--port=" + std::to_string(port_);
  pid_ = ::fork();
  if (pid_ == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl("/usr/bin/chromedriver", "chromedriver", port_arg.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  http_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
  http_->set_read_timeout(std::chrono::seconds(120));
  for (int i = 0; i < 100; ++i) {
    const auto r = http_->Get("/status");
    if (r && r->status == 200) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  json args = json::array(
      {"--headless=new", "--no-sandbox", "--disable-gpu-sandbox", "--disable-dev-shm-usage",
       "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--hide-scrollbars",
       "--force-device-scale-factor=1",
       "--window-size=" + std::to_string(width) + "," + std::to_string(height)});
  json chrome = {{"binary", "/usr/bin/chromium"}, {"args", args}};
  // Chromium keeps a window at least 500 pixels wide: a phone's width
  // comes from its device emulation (viewport, touch, user agent) instead.
  if (width < 500)
    chrome["mobileEmulation"] = {
        {"deviceMetrics", {{"width", width}, {"height", height}, {"pixelRatio", 1}}}};
  const json caps = {
      {"capabilities",
       {{"alwaysMatch", {{"browserName", "chrome"}, {"goog:chromeOptions", chrome}}}}}};
  const json r = call("POST", "/session", caps);
  session_ = r.at("sessionId").get<std::string>();
}

WebDriver::~WebDriver() {
  try {
    if (!session_.empty()) http_->Delete(("/session/" + session_).c_str());
  } catch (...) {
  }
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
}

json WebDriver::call(const std::string& method, const std::string& path, const json& body) {
  httplib::Result r =
      method == "GET" ? http_->Get(path.c_str())
      : method == "DELETE"
          ? http_->Delete(path.c_str())
          : http_->Post(path.c_str(), body.is_null() ? "{}" : body.dump(), "application/json");
  if (!r) throw std::runtime_error("chromedriver did not answer " + path);
  json j = json::parse(r->body);
  if (r->status != 200)
    throw std::runtime_error("WebDriver " + path + ": " + j["value"].value("message", r->body));
  if (j.contains("sessionId") && j["sessionId"].is_string()) return j;
  if (j["value"].is_object() && j["value"].contains("sessionId")) return j["value"];
  return j["value"];
}

void WebDriver::go(const std::string& url) {
  call("POST", "/session/" + session_ + "/url", {{"url", url}});
}

std::string WebDriver::wait_for(const std::string& css, std::chrono::milliseconds wait) {
  const auto until = std::chrono::steady_clock::now() + wait;
  for (;;) {
    const json found = call("POST", "/session/" + session_ + "/elements",
                            {{"using", "css selector"}, {"value", css}});
    if (found.is_array() && !found.empty()) return found[0][kElement].get<std::string>();
    if (std::chrono::steady_clock::now() > until)
      throw std::runtime_error("no element " + css + " on the page");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

void WebDriver::click(const std::string& element) {
  call("POST", "/session/" + session_ + "/element/" + element + "/click", json::object());
}

void WebDriver::type(const std::string& element, const std::string& text) {
  call("POST", "/session/" + session_ + "/element/" + element + "/value", {{"text", text}});
}

json WebDriver::script(const std::string& body, const json& args) {
  return call("POST", "/session/" + session_ + "/execute/sync", {{"script", body}, {"args", args}});
}

std::string WebDriver::element_by_script(const std::string& body) {
  const json e = script(body);
  if (!e.is_object() || !e.contains(kElement))
    throw std::runtime_error("the script found no element: " + body);
  return e[kElement].get<std::string>();
}

void WebDriver::drag(const std::string& element, int dx, int dy) {
  const json origin = {{kElement, element}};
  const json actions = {
      {"actions", json::array({{{"type", "pointer"},
                                {"id", "mouse"},
                                {"parameters", {{"pointerType", "mouse"}}},
                                {"actions", json::array({
                                                {{"type", "pointerMove"},
                                                 {"duration", 0},
                                                 {"origin", origin},
                                                 {"x", 0},
                                                 {"y", 0}},
                                                {{"type", "pointerDown"}, {"button", 0}},
                                                {{"type", "pointerMove"},
                                                 {"duration", 300},
                                                 {"origin", "pointer"},
                                                 {"x", dx},
                                                 {"y", dy}},
                                                {{"type", "pointerUp"}, {"button", 0}},
                                            })}}})}};
  call("POST", "/session/" + session_ + "/actions", actions);
}

cv::Mat WebDriver::screenshot() {
  const json png = call("GET", "/session/" + session_ + "/screenshot");
  const std::vector<std::uint8_t> bytes = base64_decode(png.get<std::string>());
  return cv::imdecode(bytes, cv::IMREAD_COLOR);
}

std::string WebDriver::cookie(const std::string& name) {
  const json c = call("GET", "/session/" + session_ + "/cookie/" + name);
  return c.value("value", "");
}

bool WebDriver::alert_open() {
  const auto r = http_->Get(("/session/" + session_ + "/alert/text").c_str());
  return r && r->status == 200;
}

}  // namespace rockface::office_web_test
