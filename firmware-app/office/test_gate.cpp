#include "firmware-app/office/test_gate.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace rockface::app::office_web {

void test_gate(const char* point) {
  const char* folder = std::getenv("ROCKFACE_OFFICE_TEST_GATE");
  if (!folder || !*folder) return;
  const std::filesystem::path dir(folder);
  std::ofstream(dir / (std::string(point) + ".reached")) << "reached\n";
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!std::filesystem::exists(dir / (std::string(point) + ".go")) &&
         std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

}  // namespace rockface::app::office_web
